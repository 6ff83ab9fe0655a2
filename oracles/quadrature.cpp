#include "oracles/quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {
namespace {

constexpr std::size_t kWorkspaceIntervals = 2000;

/// Switches GSL's abort-on-error handler off for one call; restores the previous handler.
class GslErrorHandlerOff {
 public:
  GslErrorHandlerOff() : previous_(gsl_set_error_handler_off()) {}
  ~GslErrorHandlerOff() { gsl_set_error_handler(previous_); }
  GslErrorHandlerOff(const GslErrorHandlerOff&) = delete;
  GslErrorHandlerOff& operator=(const GslErrorHandlerOff&) = delete;

 private:
  gsl_error_handler_t* previous_;
};

struct WorkspaceDeleter {
  void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};
using Workspace = std::unique_ptr<gsl_integration_workspace, WorkspaceDeleter>;

struct QawsTableDeleter {
  void operator()(gsl_integration_qaws_table* t) const { gsl_integration_qaws_table_free(t); }
};

/// The callable behind a gsl_function; remembers a non-finite value so that it is reported
/// instead of being integrated.
struct Trampoline {
  const Integrand* f;
  bool non_finite = false;
  double bad_x = 0.0;

  static double call(double x, void* self) {
    auto* t = static_cast<Trampoline*>(self);
    const double y = (*t->f)(x);
    if (!std::isfinite(y)) {
      if (!t->non_finite)
        t->bad_x = x;
      t->non_finite = true;
      return 0.0;
    }
    return y;
  }
};

/// Runs one QUADPACK routine `run(gsl_function*, workspace, result, abserr)`.
template <typename Run>
QuadratureResult run_quadrature(const char* routine, const Integrand& f, QuadratureTolerance tol,
                                Run run) {
  GslErrorHandlerOff handler_off;
  Workspace workspace(gsl_integration_workspace_alloc(kWorkspaceIntervals));
  if (!workspace)
    throw QuadratureFailure(std::string(routine) + ": cannot allocate workspace");
  Trampoline trampoline{&f};
  gsl_function gf{&Trampoline::call, &trampoline};
  double result = 0.0;
  double abserr = 0.0;
  const int status = run(&gf, workspace.get(), &result, &abserr);
  if (trampoline.non_finite) {
    throw QuadratureFailure(std::string(routine) +
                            ": integrand not finite at x = " + format_value(trampoline.bad_x));
  }
  // GSL_EROUND with an error estimate inside the tolerance: the routine stopped refining an
  // integral it already has (QAWC does so on a principal value that is exactly zero).
  const bool converged_anyway =
      status == GSL_EROUND && abserr <= std::max(tol.abs, tol.rel * std::abs(result));
  if (status != GSL_SUCCESS && !converged_anyway) {
    throw QuadratureFailure(std::string(routine) + ": " + gsl_strerror(status) + " (estimate " +
                            format_value(result) + ", error " + format_value(abserr) + ")");
  }
  return {result, abserr};
}

}  // namespace

QuadratureResult integrate(const Integrand& f, double lo, double hi, QuadratureTolerance tol) {
  return run_quadrature("gsl_integration_qags", f, tol,
                        [&](gsl_function* gf, gsl_integration_workspace* w, double* r, double* e) {
                          return gsl_integration_qags(gf, lo, hi, tol.abs, tol.rel,
                                                      kWorkspaceIntervals, w, r, e);
                        });
}

QuadratureResult integrate_with_breakpoints(const Integrand& f, std::span<const double> points,
                                            QuadratureTolerance tol) {
  if (points.size() < 2)
    throw QuadratureFailure("gsl_integration_qagp: needs two points");
  std::vector<double> pts(points.begin(), points.end());
  return run_quadrature("gsl_integration_qagp", f, tol,
                        [&](gsl_function* gf, gsl_integration_workspace* w, double* r, double* e) {
                          return gsl_integration_qagp(gf, pts.data(), pts.size(), tol.abs, tol.rel,
                                                      kWorkspaceIntervals, w, r, e);
                        });
}

QuadratureResult integrate_to_infinity(const Integrand& f, double lo, QuadratureTolerance tol) {
  return run_quadrature("gsl_integration_qagiu", f, tol,
                        [&](gsl_function* gf, gsl_integration_workspace* w, double* r, double* e) {
                          return gsl_integration_qagiu(gf, lo, tol.abs, tol.rel,
                                                       kWorkspaceIntervals, w, r, e);
                        });
}

QuadratureResult integrate_algebraic_ends(const Integrand& f, double lo, double hi, double alpha,
                                          double beta, QuadratureTolerance tol) {
  GslErrorHandlerOff handler_off;
  std::unique_ptr<gsl_integration_qaws_table, QawsTableDeleter> table(
      gsl_integration_qaws_table_alloc(alpha, beta, 0, 0));
  if (!table)
    throw QuadratureFailure("gsl_integration_qaws: alpha and beta must exceed -1");
  return run_quadrature("gsl_integration_qaws", f, tol,
                        [&](gsl_function* gf, gsl_integration_workspace* w, double* r, double* e) {
                          return gsl_integration_qaws(gf, lo, hi, table.get(), tol.abs, tol.rel,
                                                      kWorkspaceIntervals, w, r, e);
                        });
}

QuadratureResult integrate_cauchy_principal_value(const Integrand& f, double lo, double hi,
                                                  double c, QuadratureTolerance tol) {
  if (!(lo < c && c < hi)) {
    throw QuadratureFailure("gsl_integration_qawc: the pole c = " + format_value(c) +
                            " must lie inside (" + format_value(lo) + ", " + format_value(hi) +
                            ")");
  }
  const double d = 0.5 * std::min(c - lo, hi - c);
  const QuadratureResult centre =
      run_quadrature("gsl_integration_qawc", f, tol,
                     [&](gsl_function* gf, gsl_integration_workspace* w, double* r, double* e) {
                       return gsl_integration_qawc(gf, c - d, c + d, c, tol.abs, tol.rel,
                                                   kWorkspaceIntervals, w, r, e);
                     });
  QuadratureResult total = centre;
  const Integrand over_x_minus_c = [&f, c](double x) { return f(x) / (x - c); };
  if (lo < c - d) {
    const QuadratureResult left = integrate(over_x_minus_c, lo, c - d, tol);
    total.value += left.value;
    total.abs_error += left.abs_error;
  }
  if (c + d < hi) {
    const QuadratureResult right = integrate(over_x_minus_c, c + d, hi, tol);
    total.value += right.value;
    total.abs_error += right.abs_error;
  }
  return total;
}

}  // namespace cs::oracles
