#include "oracles/steuermann.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {
namespace {

constexpr double kPi = std::numbers::pi;

/// t - sin(t) without cancellation: its Taylor series for t < 1, directly above.
double t_minus_sin_t(double t) {
  if (t >= 1.0)
    return t - std::sin(t);
  // t^3/3! - t^5/5! + t^7/7! - ...: alternating, terms decrease fast; stop when negligible.
  double term = t * t * t / 6.0;
  double sum = term;
  for (int k = 1; k < 20; ++k) {
    term *= -t * t / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    sum += term;
    if (std::abs(term) < 1e-18 * std::abs(sum))
      break;
  }
  return sum;
}

/// D(u) = pi - 2 phi0 - sin(2 phi0) = 2u - sin(2u): the denominator of Eq. 31.
double eq31_denominator(double u) {
  return t_minus_sin_t(2.0 * u);
}

/// The right-hand side of Eq. 32 in u = pi/2 - phi0:
/// (pi - 2 phi0) / (2 sin^2 phi0) - cot(phi0) = (2u - sin 2u) / (2 cos^2 u), increasing in u.
double eq32_rhs(double u) {
  const double c = std::cos(u);
  return eq31_denominator(u) / (2.0 * c * c);
}

struct RootSolverDeleter {
  void operator()(gsl_root_fsolver* s) const { gsl_root_fsolver_free(s); }
};

/// The root of f in [lo, hi], f(lo) and f(hi) of opposite signs, by gsl_root_fsolver_brent
/// to (nearly) the last bit of the root.
template <typename F>
double brent_root(F f, double lo, double hi) {
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  struct Restore {
    gsl_error_handler_t* handler;
    ~Restore() { gsl_set_error_handler(handler); }
  } restore{previous};

  gsl_function gf{[](double x, void* params) { return (*static_cast<F*>(params))(x); }, &f};
  std::unique_ptr<gsl_root_fsolver, RootSolverDeleter> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
  if (!solver || gsl_root_fsolver_set(solver.get(), &gf, lo, hi) != GSL_SUCCESS) {
    throw std::runtime_error("brent_root: cannot bracket the root");
  }
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS)
      break;
    const double x_lo = gsl_root_fsolver_x_lower(solver.get());
    const double x_hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(x_lo, x_hi, 0.0, 4.0 * std::numeric_limits<double>::epsilon()) ==
        GSL_SUCCESS) {
      break;
    }
  }
  return gsl_root_fsolver_root(solver.get());
}

void require_contact(const char* where, const SteuermannContact& contact) {
  require_positive(where, "flat half-width b", contact.b);
  require_positive(where, "load P", contact.P);
  const double u = contact.half_pi_minus_phi0;
  if (!(u > 0.0 && u < 0.5 * kPi)) {
    throw InvalidInput(std::string(where) + ": pi/2 - phi0 must lie in (0, pi/2) (got " +
                       format_value(u) + ")");
  }
  require_positive(where, "contact half-width a", contact.contact_half_width_a);
}

/// The bracket of Eq. 31, (pi - 2 phi0) cos(phi) + L(phi), at x in [0, a], written in
/// u = pi/2 - phi0 and w = pi/2 - phi (so that phi + phi0 = pi - (u + w), phi - phi0 = u - w):
///   L = s ln sin(u + w) - cos(u) ln tan((u + w)/2) - cos(u) ln(2 cos^2((u - w)/2))
///       + ((b - x)/a) ln |sin(u - w)|,   s = sin(phi) = x / a, sin(phi0) = cos(u) = b / a.
/// This is the printed logarithm with ln|tan((phi - phi0)/2)| split into ln|sin(phi - phi0)| -
/// ln(2 cos^2((phi - phi0)/2)): the two ln|phi - phi0| singularities then carry the factor
/// sin(phi0) - sin(phi) = (b - x)/a, so the last term vanishes at x = b instead of 0 * inf.
double eq31_bracket(double u, double b, double a, double x) {
  const double s = x / a;
  const double w = std::atan2(std::sqrt((1.0 - s) * (1.0 + s)), s);
  const double cos_u = std::cos(u);
  double bracket = 2.0 * u * std::sin(w) + s * std::log(std::sin(u + w)) -
                   cos_u * std::log(std::tan(0.5 * (u + w))) -
                   cos_u * std::log(2.0 * std::pow(std::cos(0.5 * (u - w)), 2));
  const double sin_delta = std::abs(std::sin(u - w));
  if (x != b && sin_delta > 0.0)
    bracket += (b - x) / a * std::log(sin_delta);
  return bracket;
}

/// lambda / P = 2 r_e (1 - nu^2) / (b^2 E), or without (1 - nu^2): Eq. 32's coefficient.
/// Validates every parameter of the punch but its load.
double eq32_coefficient(const SteuermannPunch& punch) {
  constexpr const char* kWhere = "steuermann";
  require_positive(kWhere, "flat half-width b", punch.b);
  require_positive(kWhere, "edge radius r_e", punch.r_e);
  require_positive(kWhere, "Young's modulus E", punch.E);
  require_poisson_ratio(kWhere, punch.nu);
  if (punch.eq32_factor != Eq32Factor::kWithOneMinusNu2 &&
      punch.eq32_factor != Eq32Factor::kWithoutOneMinusNu2) {
    throw InvalidInput(std::string(kWhere) + ": unknown Eq32Factor " +
                       std::to_string(static_cast<int>(punch.eq32_factor)));
  }
  const double factor =
      punch.eq32_factor == Eq32Factor::kWithOneMinusNu2 ? 1.0 - punch.nu * punch.nu : 1.0;
  return 2.0 * punch.r_e * factor / (punch.b * punch.b * punch.E);
}

/// u = pi/2 - phi0 at which contact reaches the end of the rounded edges, a = b + r_e:
/// cos(u) = b / (b + r_e), i.e. tan(u) = (r_e (2b + r_e))^(1/2) / b (no cancellation).
double max_half_pi_minus_phi0(const SteuermannPunch& punch) {
  return std::atan2(std::sqrt(punch.r_e * (2.0 * punch.b + punch.r_e)), punch.b);
}

}  // namespace

std::string_view to_string(Eq32Factor factor) {
  switch (factor) {
    case Eq32Factor::kWithOneMinusNu2:
      return "with (1 - nu^2)";
    case Eq32Factor::kWithoutOneMinusNu2:
      return "without (1 - nu^2)";
  }
  return "unknown";
}

double steuermann_load_parameter(const SteuermannPunch& punch) {
  require_positive("steuermann", "load P", punch.P);
  return eq32_coefficient(punch) * punch.P;
}

double steuermann_max_load(const SteuermannPunch& punch) {
  return eq32_rhs(max_half_pi_minus_phi0(punch)) / eq32_coefficient(punch);
}

SteuermannContact steuermann_contact(const SteuermannPunch& punch) {
  constexpr const char* kWhere = "steuermann_contact";
  const double lambda = steuermann_load_parameter(punch);
  const double u_max = max_half_pi_minus_phi0(punch);
  const double rhs_max = eq32_rhs(u_max);
  if (lambda > rhs_max) {
    throw InvalidInput(std::string(kWhere) + ": load P = " + format_value(punch.P) +
                       " would spread contact past the rounded edges (a > b + r_e = " +
                       format_value(punch.b + punch.r_e) +
                       "); the largest load is P = " + format_value(punch.P * rhs_max / lambda));
  }
  if (!(lambda >= std::numeric_limits<double>::min())) {
    throw InvalidInput(std::string(kWhere) + ": load P = " + format_value(punch.P) +
                       " too small: the load parameter of Eq. 32 underflows");
  }
  const double u =
      lambda == rhs_max
          ? u_max
          : brent_root([lambda](double v) { return eq32_rhs(v) - lambda; }, 0.0, u_max);
  if (!(u > 0.0) || !(eq31_denominator(u) > 0.0)) {
    throw InvalidInput(std::string(kWhere) + ": load P = " + format_value(punch.P) +
                       " too small to resolve phi0 < pi/2");
  }
  return {
      .b = punch.b,
      .P = punch.P,
      .phi0 = 0.5 * kPi - u,
      .half_pi_minus_phi0 = u,
      .contact_half_width_a = punch.b / std::cos(u),
  };
}

double steuermann_pressure(const SteuermannContact& contact, double x) {
  constexpr const char* kWhere = "steuermann_pressure";
  require_contact(kWhere, contact);
  require_finite(kWhere, "position x", x);
  const double a = contact.contact_half_width_a;
  const double abs_x = std::abs(x);
  if (abs_x >= a)
    return 0.0;
  const double u = contact.half_pi_minus_phi0;
  const double bracket = eq31_bracket(u, contact.b, a, abs_x);
  const double pressure = contact.P / a * (2.0 / kPi) / eq31_denominator(u) * bracket;
  // Rounding can leave a tiny negative value next to x = a, where the pressure -> 0.
  return pressure > 0.0 ? pressure : 0.0;
}

SteuermannPeak steuermann_peak(const SteuermannContact& contact) {
  constexpr const char* kWhere = "steuermann_peak";
  require_contact(kWhere, contact);
  const double u = contact.half_pi_minus_phi0;
  // dp/dphi ~ h(psi), psi = phi - phi0 in (0, u]: with cos(phi) = sin(u - psi),
  // sin(phi) = cos(u - psi), sin(phi + phi0) = sin(2u - psi):
  //   h = sin(u - psi) ln(sin(2u - psi) / sin(psi)) - 2u cos(u - psi),
  // +inf at psi -> 0+, -2u at psi = u (phi = pi/2, x = a).
  auto h = [u](double psi) {
    return std::sin(u - psi) * std::log(std::sin(2.0 * u - psi) / std::sin(psi)) -
           2.0 * u * std::cos(u - psi);
  };
  double psi_lo = 1e-6 * u;
  while (!(h(psi_lo) > 0.0)) {
    psi_lo *= 1e-6;
    if (!(psi_lo > 0.0))
      throw InvalidInput(std::string(kWhere) + ": cannot bracket the peak");
  }
  const double psi = brent_root(h, psi_lo, u);
  const double a = contact.contact_half_width_a;
  const double x_peak = a * std::cos(u - psi);
  return {
      .peak_pressure = steuermann_pressure(contact, x_peak),
      .x_peak = x_peak,
      .phi_peak = contact.phi0 + psi,
  };
}

SteuermannPunch steuermann_study_punch(const SteuermannStudyCase& study_case) {
  constexpr const char* kWhere = "steuermann_study_punch";
  require_positive(kWhere, "flat half-width b", study_case.b);
  require_positive(kWhere, "edge radius r_e", study_case.r_e);
  require_positive(kWhere, "Young's modulus E", study_case.E);
  require_positive(kWhere, "relative pressure p/E", study_case.p_over_E);
  const double p = study_case.p_over_E * study_case.E;
  return {
      .b = study_case.b,
      .r_e = study_case.r_e,
      .P = 2.0 * (study_case.b + study_case.r_e) * p,
      .E = study_case.E,
      .nu = study_case.nu,
      .eq32_factor = study_case.eq32_factor,
  };
}

double steuermann_study_pressure(const SteuermannPunch& punch) {
  constexpr const char* kWhere = "steuermann_study_pressure";
  require_positive(kWhere, "flat half-width b", punch.b);
  require_positive(kWhere, "edge radius r_e", punch.r_e);
  require_positive(kWhere, "load P", punch.P);
  return punch.P / (2.0 * (punch.b + punch.r_e));
}

}  // namespace cs::oracles
