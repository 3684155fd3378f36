#pragma once
/// \file contact_offset.hpp
/// The squared distance between offset surfaces: panels of thickness t whose mid-surfaces
/// are a distance d apart have a gap g = d - t between their faces (the offset surfaces of
/// codimensional IPC, Li et al. 2021; here the barrier is of the gap's square itself).
///
///     mid-surface a  ==================      - - - face of a (t/2 off its mid-surface)
///                          | g = d - t       - - - face of b
///     mid-surface b  ==================      d: the mid-surfaces' distance
///
/// The barrier takes the squared gap s_o = (sqrt(s) - t)^2 in place of the squared distance
/// s = d^2, with derivatives by the chain rule: ds_o/ds = 1 - t/d and d^2 s_o/ds^2 =
/// t / (2 d^3), so with the gradient g_s and Hessian H_s of s,
///
///     grad s_o = (1 - t/d) g_s,     hess s_o = (1 - t/d) H_s + t / (2 d^3) g_s g_s^T.
///
/// d_hat is then measured from the faces: a pair acts while d < t + d_hat.

#include "kresling/contact/contact_distance.hpp"

namespace kresling::contact {

/// The squared gap (d - offset)^2 with its gradient and (when `with_hessian`) Hessian, from
/// the squared distance s = d^2 with its derivatives, for an offset >= 0 [length]: the
/// distance itself (unchanged, to the bit) when the offset is 0; a value of 0 with zero
/// derivatives (the barrier's "touching or crossing") when d <= offset, where the faces
/// touch or overlap.
template <int N>
ScalarDerivatives<N> offset_squared_distance(const ScalarDerivatives<N>& distance, double offset,
                                             bool with_hessian = true);

}  // namespace kresling::contact
