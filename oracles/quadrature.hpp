#pragma once
// Adaptive quadrature on GSL's QUADPACK routines, for integrating oracle fields: resultants of
// contact pressures, superpositions of point-load solutions, principal values of surface
// displacement integrals. Thin wrappers: a C++ callable in, value and error estimate out.
//
// Each call runs with GSL's error handler switched off (restored on return) and reports a
// routine that did not reach the requested tolerance by throwing QuadratureFailure, never
// by aborting the program. The handler swap touches GSL's global handler pointer: do not
// change it concurrently from another thread.

#include <functional>
#include <span>
#include <stdexcept>
#include <string>

namespace cs::oracles {

/// A quadrature that did not reach its tolerance (GSL status other than GSL_SUCCESS), or
/// whose integrand returned a non-finite value.
class QuadratureFailure : public std::runtime_error {
 public:
  explicit QuadratureFailure(const std::string& what) : std::runtime_error(what) {}
};

/// Requested accuracy: GSL stops when |error| <= max(abs, rel * |integral|).
struct QuadratureTolerance {
  double abs = 0.0;
  double rel = 1e-12;
};

/// An integral and GSL's estimate of its absolute error.
struct QuadratureResult {
  double value;
  double abs_error;
};

using Integrand = std::function<double(double)>;

/// Integral of f over [lo, hi] (QAGS: adaptive Gauss-Kronrod 21 with Wynn extrapolation;
/// copes with integrable end-point singularities such as inverse square roots).
QuadratureResult integrate(const Integrand& f, double lo, double hi, QuadratureTolerance tol);

/// Integral of f over [points.front(), points.back()], with known difficult points (kinks,
/// log singularities, near-singular peaks) between them (QAGP). points must be increasing.
QuadratureResult integrate_with_breakpoints(const Integrand& f, std::span<const double> points,
                                            QuadratureTolerance tol);

/// Integral of f over [lo, +inf) (QAGIU, on the map x = lo + (1 - t)/t).
QuadratureResult integrate_to_infinity(const Integrand& f, double lo, QuadratureTolerance tol);

/// Integral of f(x) (x - lo)^alpha (hi - x)^beta over [lo, hi], alpha, beta > -1 (QAWS:
/// the algebraic end singularities are integrated exactly by modified Clenshaw-Curtis).
QuadratureResult integrate_algebraic_ends(const Integrand& f, double lo, double hi, double alpha,
                                          double beta, QuadratureTolerance tol);

/// Cauchy principal value of the integral of f(x) / (x - c) over [lo, hi], lo < c < hi: QAWC
/// on the interval centred on c reaching halfway to the nearer end, QAGS on the rest, so f may
/// have integrable end singularities (an inverse square root, a square root) at lo and hi.
QuadratureResult integrate_cauchy_principal_value(const Integrand& f, double lo, double hi,
                                                  double c, QuadratureTolerance tol);

}  // namespace cs::oracles
