#include "kresling/model/family_registry.hpp"

#include <stdexcept>

#include "kresling/model/bar_family.hpp"
#include "kresling/model/cable_family.hpp"
#include "kresling/model/face_angle_family.hpp"
#include "kresling/model/force_family.hpp"
#include "kresling/model/hinge_family.hpp"
#include "kresling/model/plane_contact_family.hpp"
#include "kresling/model/self_contact_family.hpp"
#include "kresling/model/spring_family.hpp"

namespace kresling::model {

const std::vector<FamilyKind>& family_kinds() {
  // One line per family. Bars, hinges and cables come first, in this order: it is the order
  // their contributions have always been summed in, which the reference runs reproduce to
  // the last bit.
  static const std::vector<FamilyKind> kinds = {
      {"bars", &BarFamily::from_table, "axial bars between two nodes"},
      {"hinges", &HingeFamily::from_table, "rotational springs on the dihedral angle of four nodes"},
      {"cables", &CableFamily::from_table, "tension-only cables sliding through guide nodes"},
      {"springs", &SpringFamily::from_table, "zero-length springs tying nodes to fixed points"},
      {"contact", &PlaneContactFamily::from_table, "nodes kept off rigid planes by a barrier"},
      {"self_contact", &SelfContactFamily::from_table,
       "panels (triangles) kept off each other by a barrier"},
      {"face_angles", &FaceAngleFamily::from_table,
       "springs on the interior angles of triangles (the panels' in-plane shear)"},
      {"forces", &ForceFamily::from_table, "forces held at nodes (dead loads)"},
  };
  return kinds;
}

const FamilyKind& family_kind(const std::string& name) {
  std::string known;
  for (const FamilyKind& kind : family_kinds()) {
    if (name == kind.name) return kind;
    known += (known.empty() ? "" : ", ") + std::string(kind.name);
  }
  throw std::invalid_argument("element family '" + name + "' is unknown: must be one of " + known);
}

}  // namespace kresling::model
