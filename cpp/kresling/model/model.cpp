#include "kresling/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/model/family_registry.hpp"

namespace kresling::model {

namespace {

double extent(const NodeMatrix& X) {
  return std::max((X.colwise().maxCoeff() - X.colwise().minCoeff()).norm(), 1e-300);
}

// Position of family `name` in the registry, or the registry's size for an unregistered one.
std::size_t registry_rank(const std::string& name) {
  const auto& kinds = family_kinds();
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    if (name == kinds[i].name) return i;
  }
  return kinds.size();
}

}  // namespace

void check_hinge_geometry(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                          std::size_t index) {
  check_hinge_geometry(X, nodes, index, extent(X));
}

void check_hinge_geometry_at_scale(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                                   std::size_t index, double scale) {
  check_hinge_geometry(X, nodes, index, scale);
}

double node_extent(const NodeMatrix& X) { return extent(X); }

Model::Model(NodeMatrix nodes, std::vector<Bar> bars, std::vector<Hinge> hinges,
             std::vector<std::uint8_t> fixed, std::vector<Cable> cables)
    : nodes_(std::move(nodes)), fixed_(std::move(fixed)) {
  adopt({std::make_shared<BarFamily>(std::move(bars)),
         std::make_shared<HingeFamily>(std::move(hinges)),
         std::make_shared<CableFamily>(std::move(cables))});
  validate();
}

Model::Model(NodeMatrix nodes, std::vector<std::uint8_t> fixed, std::vector<FamilyPtr> families)
    : nodes_(std::move(nodes)), fixed_(std::move(fixed)) {
  adopt(std::move(families));
  validate();
}

void Model::adopt(std::vector<FamilyPtr> families) {
  for (const auto& f : families) {
    if (!f) throw std::invalid_argument("families: contains a null family");
  }
  // Registered families in the registry's order, the others after them as given.
  std::stable_sort(families.begin(), families.end(), [](const FamilyPtr& a, const FamilyPtr& b) {
    return registry_rank(a->name()) < registry_rank(b->name());
  });
  for (std::size_t i = 1; i < families.size(); ++i) {
    if (std::string(families[i]->name()) == families[i - 1]->name()) {
      throw std::invalid_argument(std::string("families: '") + families[i]->name() +
                                  "' is given twice");
    }
  }
  families_ = std::move(families);
  bars_ = find<BarFamily>();
  hinges_ = find<HingeFamily>();
  cables_ = find<CableFamily>();
  // The built-in families are always there, so that bars(), hinges() and cables() are too.
  std::vector<FamilyPtr> missing;
  if (!bars_) missing.push_back(std::make_shared<BarFamily>(std::vector<Bar>{}));
  if (!hinges_) missing.push_back(std::make_shared<HingeFamily>(std::vector<Hinge>{}));
  if (!cables_) missing.push_back(std::make_shared<CableFamily>(std::vector<Cable>{}));
  if (!missing.empty()) {
    missing.insert(missing.end(), families_.begin(), families_.end());
    adopt(std::move(missing));
  }
}

void Model::validate() const {
  if (nodes_.rows() == 0) throw std::invalid_argument("nodes: the model has no nodes");
  for (Index i = 0; i < nodes_.rows(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(nodes_(i, k))) {
        throw std::invalid_argument("node " + std::to_string(i) + ": coordinate " +
                                    std::to_string(k) + " = " + format_number(nodes_(i, k)) +
                                    " is not finite");
      }
    }
  }
  if (static_cast<Index>(fixed_.size()) != num_dofs()) {
    throw std::invalid_argument("fixed: has " + std::to_string(fixed_.size()) +
                                " entries, must have one per DOF (" +
                                std::to_string(num_dofs()) + ")");
  }
  // Length scale for the degeneracy checks: the model's extent.
  const double scale = extent(nodes_);
  for (const auto& f : families_) f->check(nodes_, scale);
}

const ElementFamily* Model::family(const std::string& name) const {
  for (const auto& f : families_) {
    if (name == f->name()) return f.get();
  }
  return nullptr;
}

Model Model::with_family(FamilyPtr family) const {
  if (!family) throw std::invalid_argument("family: is null");
  const auto same = [&](const FamilyPtr& f) { return std::string(f->name()) == family->name(); };
  const auto it = std::find_if(families_.begin(), families_.end(), same);
  if (it == families_.end()) {
    std::vector<FamilyPtr> families = families_;
    families.push_back(std::move(family));
    return Model(nodes_, fixed_, std::move(families));
  }
  // The rest of the model was validated when it was built: check only the new family (a
  // path that changes one family's parameters at every increment pays for that one).
  family->check(nodes_, extent(nodes_));
  Model copy = *this;
  copy.families_[static_cast<std::size_t>(it - families_.begin())] = std::move(family);
  copy.bars_ = copy.find<BarFamily>();
  copy.hinges_ = copy.find<HingeFamily>();
  copy.cables_ = copy.find<CableFamily>();
  if (!copy.bars_ || !copy.hinges_ || !copy.cables_) {
    throw std::invalid_argument("family: a built-in family must keep its type");
  }
  return copy;
}

Model Model::with_cable_rest_lengths(const std::vector<double>& rest_lengths) const {
  const auto& cables = this->cables();
  if (rest_lengths.size() != cables.size()) {
    throw std::invalid_argument("rest_lengths: has " + std::to_string(rest_lengths.size()) +
                                " entries, the model has " + std::to_string(cables.size()) +
                                " cables");
  }
  std::vector<Cable> changed = cables;
  for (std::size_t i = 0; i < rest_lengths.size(); ++i) {
    require_positive("rest_lengths[" + std::to_string(i) + "]", rest_lengths[i]);
    changed[i].rest_length = rest_lengths[i];
  }
  return with_family(std::make_shared<CableFamily>(std::move(changed)));
}

NodeMatrix Model::deformed(const VectorX& u) const {
  if (u.size() != num_dofs()) {
    throw std::invalid_argument("u: has " + std::to_string(u.size()) + " entries, must have " +
                                std::to_string(num_dofs()));
  }
  return nodes_ + Eigen::Map<const NodeMatrix>(u.data(), nodes_.rows(), 3);
}

}  // namespace kresling::model
