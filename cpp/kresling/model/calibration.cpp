#include "kresling/model/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "kresling/core/check.hpp"

namespace kresling::model {

namespace {

using Edge = std::array<Index, 2>;

Edge make_edge(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// Bend stiffness per unit length of a spoke whose diagonal through the centre is `dsl`.
double bend_per_length(double rigidity, double dsl, double t) {
  return rigidity * std::cbrt(dsl / t) / dsl;
}

// Corner positions sorted by vertex index: rank r holds the local corner of the r-th
// smallest vertex (how MERLIN2 v1.1 orders a panel's spokes when it assigns them values).
std::vector<std::size_t> ranked_corners(const std::vector<Index>& panel) {
  std::vector<std::size_t> order(panel.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return panel[a] < panel[b]; });
  return order;
}

struct Calibrator {
  const PanelElements& e;
  double t, nu, rigidity;
  bool compat;
  std::map<Edge, Index> fold_bar, boundary_bar;  // side -> bar index (first bar on a fold)
  Index first_bend_of_panel = 0;
  SheetStiffness out;

  // The bar on side (a, b) of a panel, or -1. `is_fold` says which kind it is.
  Index side_bar(const Edge& side, bool* is_fold = nullptr) const {
    if (auto it = fold_bar.find(side); it != fold_bar.end()) {
      if (is_fold) *is_fold = true;
      return it->second;
    }
    if (is_fold) *is_fold = false;
    auto it = boundary_bar.find(side);
    return it == boundary_bar.end() ? -1 : it->second;
  }

  std::vector<Edge> sides(const std::vector<Index>& panel) const {
    std::vector<Edge> s;
    for (std::size_t k = 0; k < panel.size(); ++k) {
      s.push_back(make_edge(panel[k], panel[(k + 1) % panel.size()]));
    }
    return s;
  }

  double length(const Edge& s) const { return (e.nodes.row(s[1]) - e.nodes.row(s[0])).norm(); }

  void add_area(Index bar, double area) {
    if (bar >= 0) out.bar_area[static_cast<std::size_t>(bar)] += area;
  }

  // Spoke values in corner order go to the spokes' bend hinges (and bars, which share the
  // bend hinges' indices): each to its own spoke, or, in MERLIN2 v1.1's pairing, to the
  // spokes ranked by vertex index.
  void add_spokes(const std::vector<Index>& panel, const std::vector<double>& kb,
                  const std::vector<double>& area) {
    const auto ranked = ranked_corners(panel);
    for (std::size_t k = 0; k < panel.size(); ++k) {
      const std::size_t target = compat ? ranked[k] : k;
      const Index bend = first_bend_of_panel + static_cast<Index>(target);
      out.bend_stiffness[static_cast<std::size_t>(bend)] += kb[k];
      add_area(bend, area[k]);
    }
  }

  void triangle(const std::vector<Index>& panel) {
    const auto s = sides(panel);
    double perimeter = 0.0;
    for (const Edge& side : s) perimeter += length(side);
    const Vector3 a = e.nodes.row(panel[0]), b = e.nodes.row(panel[1]), c = e.nodes.row(panel[2]);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (const Edge& side : s) add_area(side_bar(side), t * 2.0 * area / (perimeter * (1.0 - nu)));
  }

  void quad(const std::vector<Index>& panel, Index centre) {
    const auto s = sides(panel);
    std::vector<double> lf, lb;
    for (const Edge& side : s) lf.push_back(length(side));
    for (Index v : panel) lb.push_back((e.nodes.row(v) - e.nodes.row(centre)).norm());
    std::vector<double> kb(4);
    for (int k = 0; k < 4; ++k) kb[k] = bend_per_length(rigidity, lb[k] + lb[(k + 2) % 4], t);
    const double W = 0.5 * (lf[0] + lf[2]), H = 0.5 * (lf[1] + lf[3]);
    const double c = 1.0 - nu * nu;
    std::vector<double> af = {t * std::abs(H * H - nu * W * W) / (2.0 * H * c),
                              t * std::abs(W * W - nu * H * H) / (2.0 * W * c)};
    af = {af[0], af[1], af[0], af[1]};
    const double ab = t * nu * std::pow(H * H + W * W, 1.5) / (2.0 * H * W * c);
    add_spokes(panel, kb, std::vector<double>(4, ab));

    std::vector<Index> bars(4);
    int folds = 0;
    for (int k = 0; k < 4; ++k) {
      bool is_fold = false;
      bars[k] = side_bar(s[k], &is_fold);
      folds += is_fold;
    }
    if (compat && folds == 4) {
      // MERLIN2 v1.1 pairs the side areas (in corner order) with the sides ranked by
      // (lower vertex, higher vertex) when all four sides are folds.
      std::vector<int> ranked = {0, 1, 2, 3};
      std::sort(ranked.begin(), ranked.end(), [&](int x, int y) { return s[x] < s[y]; });
      for (int r = 0; r < 4; ++r) add_area(bars[ranked[r]], af[r]);
    } else {
      for (int k = 0; k < 4; ++k) add_area(bars[k], af[k]);
    }
  }

  void polygon(const std::vector<Index>& panel, Index centre) {
    const std::size_t m = panel.size();
    const auto s = sides(panel);
    const Vector3 x = e.nodes.row(centre);
    std::vector<Vector3> spoke;
    std::vector<double> lb;
    double perimeter = 0.0, spokes = 0.0, area = 0.0;
    for (const Edge& side : s) perimeter += length(side);
    for (Index v : panel) {
      spoke.push_back(Vector3(e.nodes.row(v)) - x);
      lb.push_back(spoke.back().norm());
      spokes += lb.back();
    }
    for (std::size_t k = 0; k < m; ++k) area += 0.5 * spoke[k].cross(spoke[(k + 1) % m]).norm();
    const double share = t * 2.0 * area / ((perimeter + spokes) * (1.0 - nu));
    std::vector<double> kb(m);
    for (std::size_t k = 0; k < m; ++k) {
      // The spoke most nearly opposite (smallest cosine; the first on a tie).
      std::size_t opposite = 0;
      double lowest = INFINITY;
      for (std::size_t j = 0; j < m; ++j) {
        const double cosine = spoke[j].dot(spoke[k]) / (lb[j] * lb[k]);
        if (cosine < lowest) lowest = cosine, opposite = j;
      }
      kb[k] = bend_per_length(rigidity, lb[k] + lb[opposite], t);
    }
    add_spokes(panel, kb, std::vector<double>(m, share));
    for (const Edge& side : s) add_area(side_bar(side), share);
  }
};

}  // namespace

SheetStiffness calibrate_sheet(const PanelElements& elements,
                               const std::vector<std::vector<Index>>& panels,
                               const SheetMaterial& material, bool merlin2_compat) {
  require_positive("youngs_modulus", material.youngs_modulus);
  require_positive("thickness", material.thickness);
  require_finite("poisson_ratio", material.poisson_ratio);
  if (!(material.poisson_ratio > -1.0 && material.poisson_ratio <= 0.5)) {
    throw_invalid("poisson_ratio", material.poisson_ratio, "in (-1, 0.5]");
  }
  require_positive("length_scale", material.length_scale, /*allow_zero=*/true);
  if (panels.size() != elements.panel_centre.size()) {
    throw std::invalid_argument("panels: not the panels these elements were built from");
  }

  const double E = material.youngs_modulus, t = material.thickness, nu = material.poisson_ratio;
  Calibrator c{elements, t, nu, E * t * t * t / (12.0 * (1.0 - nu * nu)), merlin2_compat,
               {}, {}, 0, {}};
  const auto bars = elements.bars();
  const Index nb = static_cast<Index>(elements.bends.size());
  const Index nf = static_cast<Index>(elements.folds.size());
  for (Index f = 0; f < nf; ++f) {
    const auto& h = elements.folds[static_cast<std::size_t>(f)];
    c.fold_bar.emplace(make_edge(h[0], h[1]), nb + f);  // emplace keeps the first
  }
  for (std::size_t k = 0; k < elements.boundary.size(); ++k) {
    c.boundary_bar.emplace(elements.boundary[k], nb + nf + static_cast<Index>(k));
  }
  c.out.bar_area.assign(bars.size(), 0.0);
  c.out.bend_stiffness.assign(elements.bends.size(), 0.0);

  // Folds: D / Ls and 0.55 D (Lf / t)^(1/3) in series, per unit length.
  std::vector<double> lf;
  for (const auto& h : elements.folds) lf.push_back(c.length({h[0], h[1]}));
  double ls = material.length_scale;
  if (ls == 0.0 && !lf.empty()) {
    ls = 2.0 * std::accumulate(lf.begin(), lf.end(), 0.0) / static_cast<double>(lf.size());
  }
  c.out.length_scale = ls;
  for (double l : lf) {
    const double kl = c.rigidity / ls, km = 0.55 * c.rigidity * std::cbrt(l / t);
    c.out.fold_stiffness.push_back(1.0 / (1.0 / kl + 1.0 / km) / l);
  }

  for (std::size_t p = 0; p < panels.size(); ++p) {
    const auto& panel = panels[p];
    const Index centre = elements.panel_centre[p];
    if (panel.size() == 3) {
      c.triangle(panel);
      continue;
    }
    if (centre < 0) {
      throw std::invalid_argument("panel " + std::to_string(p) +
                                  ": has no centre node; material calibration needs the N5B8 "
                                  "split");
    }
    if (panel.size() == 4) {
      c.quad(panel, centre);
    } else {
      c.polygon(panel, centre);
    }
    c.first_bend_of_panel += static_cast<Index>(panel.size());
  }
  // MERLIN2's quad formulas give zero area where nu = 0 (the spokes, t nu (H^2 + W^2)^1.5 /
  // (2 H W (1 - nu^2))) or H^2 = nu W^2 (a pair of sides): say so, naming the material,
  // rather than leave the model's check to refuse a bar of zero area it cannot explain.
  for (std::size_t b = 0; b < bars.size(); ++b) {
    if (!(c.out.bar_area[b] > 0.0) || !std::isfinite(c.out.bar_area[b])) {
      throw std::invalid_argument(
          "poisson_ratio = " + format_number(nu) + " is invalid for this pattern: it gives bar " +
          std::to_string(b) + " (nodes " + std::to_string(bars[b][0]) + ", " +
          std::to_string(bars[b][1]) + ") a calibrated area of " +
          format_number(c.out.bar_area[b]) +
          "; must make every area > 0 (MERLIN2's quad calibration: a quad's spokes get t nu "
          "(H^2 + W^2)^1.5 / (2 H W (1 - nu^2)), zero at nu = 0; its sides t |H^2 - nu W^2| / "
          "(2 H (1 - nu^2)), zero where H^2 = nu W^2), or give the areas (manual calibration)");
    }
  }
  return c.out;
}

}  // namespace kresling::model
