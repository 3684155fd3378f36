#pragma once
/// \file design.hpp
/// Generalized Kresling cell geometry (thesis ch. 2, eqns 1-9; docs/thesis_equations.md,
/// 'Geometry').
///
/// One cell: a bottom and a top regular n-gon of circumradius R, the top twisted by alpha
/// and raised by L(alpha). Bottom vertex i sits at angle 2 pi i / n, top vertex i at
/// 2 pi i / n + alpha. The valley crease joins bottom i to top i+1 (length Vg, constant on
/// the truss path); the mountain crease joins bottom i to top i (length m(alpha)).
///
///         t_i ______ t_{i+1}          chirality +1:
///            \ ``-._ \                  triangles [b_i, b_{i+1}, t_{i+1}], [b_i, t_{i+1}, t_i]
///    mountain \  valley`-.\             valley   b_i - t_{i+1}
///              \______`-._\             mountain b_i - t_i
///            b_i          b_{i+1}
///
/// Units: lengths in mm, angles in rad.

#include <array>
#include <string>

namespace kresling::geometry {

/// The two stable states of a cell; the integer values are the thesis's (0 and 1).
enum class State : int { Contracted = 0, Extended = 1 };

/// Design variables of one cell.
struct DesignParameters {
  int n = 0;           ///< sides of the base polygon, >= 3
  double R = 0.0;      ///< circumradius of the base polygon [mm], > 0
  double lam = 0.0;    ///< angle ratio lambda, 0.5 < lam < 1
  double Lc = 0.0;     ///< contracted height [mm], >= 0
  int chirality = 1;   ///< +1 or -1 (the sign of lambda in the thesis's code)
};

/// Every derived quantity of docs/thesis_equations.md, 'Geometry'.
struct DerivedQuantities {
  double phi = 0;      ///< pi / n
  double gamma = 0;    ///< half the polygon's internal angle, eqn 2
  double P = 0;        ///< polygon side, eqn 1
  double V = 0;        ///< traditional valley crease, eqn 3
  double M = 0;        ///< traditional mountain crease, eqn 4
  double Vg = 0;       ///< generalized valley crease, eqn 6
  double Mg = 0;       ///< generalized mountain crease, eqn 7
  double theta_g = 0;  ///< facet angle of the flat pattern (between P and Vg), eqn 5
  double alpha0 = 0;   ///< twist at the contracted state, 2 lam gamma
  double alpha_e = 0;  ///< twist at the extended state, pi - alpha0 - 2 phi = 2 gamma (1 - lam)
  double Le = 0;       ///< extended height
  double psi_con = 0;  ///< facet angle Psi (perimeter triangle vs base polygon), contracted
  double psi_ext = 0;  ///< facet angle Psi, extended
};

/// Names of the quantities in the order `derived_as_array` writes them.
inline constexpr std::array<const char*, 13> kDerivedNames = {
    "phi", "gamma", "P", "V", "M", "Vg", "Mg", "theta_g",
    "alpha0", "alpha_e", "Le", "Psi_con", "Psi_ext"};

/// Throw std::invalid_argument naming the parameter when `p` is outside the design space.
/// `suffix` is appended to parameter names in messages (e.g. "[12]" for a batch entry).
void validate(const DesignParameters& p, const std::string& suffix = "");

/// Derived quantities of a valid design (call `validate` first).
DerivedQuantities derive(const DesignParameters& p);

/// `d` in the order of kDerivedNames.
std::array<double, kDerivedNames.size()> derived_as_array(const DerivedQuantities& d);

/// A validated design with its derived quantities (immutable).
class Design {
 public:
  /// Throws std::invalid_argument for parameters outside the design space.
  Design(int n, double R, double lam, double Lc, int chirality = 1);
  explicit Design(const DesignParameters& p);

  const DesignParameters& parameters() const { return p_; }
  const DerivedQuantities& derived() const { return d_; }

  /// Twist of the top polygon relative to the bottom one in a stable state [rad]
  /// (unsigned; a cell of chirality -1 twists by -twist(state)).
  double twist(State state) const;
  /// Height of the cell in a stable state [mm].
  double height(State state) const;

  /// L(alpha), eqn 8: cell height on the truss path at twist alpha [mm].
  /// Throws when L(alpha)^2 < 0 (alpha beyond where the valley bars can reach).
  double height_at(double alpha) const;
  /// m(alpha), eqn 9: mountain bar length on the truss path [mm].
  double mountain_length_at(double alpha) const;
  /// Psi(alpha): interior dihedral angle between a perimeter triangle and the base polygon
  /// along a polygon edge, on the truss path [rad], in (0, pi).
  double facet_angle_at(double alpha) const;

 private:
  DesignParameters p_;
  DerivedQuantities d_;
};

}  // namespace kresling::geometry
