#include "oracles/steuermann.hpp"

#include <algorithm>
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
constexpr double kQuarterPi = 0.25 * kPi;

// Domain limits (see steuermann.hpp).
constexpr double kMinLoadParameter = 1e-300;
constexpr double kMinEdgeRatio = 1e-100;
constexpr double kMaxEdgeRatio = 1e100;

/// Sum of an alternating or positive power series term(k), k = 0, 1, ..., until negligible.
template <typename Term>
double sum_series(Term term) {
  double sum = 0.0;
  for (int k = 0; k < 60; ++k) {
    const double t = term(k);
    sum += t;
    if (std::abs(t) <= 1e-18 * std::abs(sum))
      break;
  }
  return sum;
}

/// t - sin(t) without cancellation: its Taylor series for t < 1, directly above.
double t_minus_sin_t(double t) {
  if (t >= 1.0)
    return t - std::sin(t);
  // t^3/3! - t^5/5! + t^7/7! - ...
  double term = t * t * t / 6.0;
  return sum_series([&](int k) {
    if (k > 0)
      term *= -t * t / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    return term;
  });
}

/// sin(t) - t cos(t) = sum_k>=1 (-1)^(k+1) 2k t^(2k+1) / (2k+1)!, without cancellation.
double sin_minus_t_cos_t(double t) {
  if (t >= 1.0)
    return std::sin(t) - t * std::cos(t);
  double power = t * t * t / 6.0;  // t^(2k+1) / (2k+1)! at k = 1
  return sum_series([&](int k) {
    if (k > 0)
      power *= -t * t / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    return 2.0 * (k + 1) * power;
  });
}

/// artanh(tau) for 0 <= tau < 1, given 1 - tau separately (accurate next to 1).
double artanh_near_one(double tau, double one_minus_tau) {
  if (tau < 0.5)
    return std::atanh(tau);
  return 0.5 * (std::log1p(tau) - std::log(one_minus_tau));
}

/// artanh(tau) - tau without cancellation, |tau| < 1 (1 - |tau| given separately).
double artanh_minus_identity(double tau, double one_minus_abs_tau) {
  const double t = std::abs(tau);
  double r = 0.0;
  if (t < 0.25) {
    double power = t * t * t;  // tau^3/3 + tau^5/5 + ...
    r = sum_series([&](int k) {
      if (k > 0)
        power *= t * t;
      return power / (2.0 * k + 3.0);
    });
  } else {
    r = artanh_near_one(t, one_minus_abs_tau) - t;
  }
  return std::copysign(r, tau);
}

/// The angles of a solved contact: u = pi/2 - phi0 and phi0, each to full relative precision
/// when it is the smaller (light loads: u small; heavy loads or r_e >> b: phi0 small).
struct EdgeAngles {
  double u;
  double phi0;
  double sin_u;  ///< = cos(phi0)
  double cos_u;  ///< = sin(phi0) = b / a
  bool small_u;  ///< u <= pi/4: u is the accurate one
};

EdgeAngles edge_angles(double u, double phi0) {
  if (u <= kQuarterPi)
    return {u, phi0, std::sin(u), std::cos(u), true};
  return {u, phi0, std::cos(phi0), std::sin(phi0), false};
}

/// D = pi - 2 phi0 - sin(2 phi0) = 2u - sin 2u: the denominator of Eq. 31.
double eq31_denominator(const EdgeAngles& e) {
  return e.small_u ? t_minus_sin_t(2.0 * e.u) : kPi - 2.0 * e.phi0 - std::sin(2.0 * e.phi0);
}

/// The right-hand side of Eq. 32, (pi - 2 phi0) / (2 sin^2 phi0) - cot(phi0) = D / (2 cos^2 u).
double eq32_rhs(const EdgeAngles& e) {
  return eq31_denominator(e) / (2.0 * e.cos_u * e.cos_u);
}

/// A point of the contact by its angle: sin(phi) = x / a, w = pi/2 - phi, both kept, each
/// accurate when it is the smaller.
struct PointAngles {
  double w;
  double phi;
  [[nodiscard]] double sin_w() const { return w <= kQuarterPi ? std::sin(w) : std::cos(phi); }
  [[nodiscard]] double cos_w() const { return w <= kQuarterPi ? std::cos(w) : std::sin(phi); }
};

/// u - w = phi - phi0 and cos((u + w)/2) = sin((phi + phi0)/2), from the accurate angles.
double u_minus_w(const EdgeAngles& e, const PointAngles& at) {
  return (!e.small_u && at.phi <= kQuarterPi) ? at.phi - e.phi0 : e.u - at.w;
}
double cos_half_u_plus_w(const EdgeAngles& e, const PointAngles& at) {
  const double half_sum = 0.5 * (e.u + at.w);
  return half_sum <= kQuarterPi ? std::cos(half_sum) : std::sin(0.5 * (at.phi + e.phi0));
}

/// tau2 = min(sin u / sin w, sin w / sin u) and 1 - tau2, without cancellation.
struct SineRatio {
  double tau;
  double one_minus_tau;
};
SineRatio sine_ratio(const EdgeAngles& e, const PointAngles& at) {
  const double sin_w = at.sin_w();
  const double diff = u_minus_w(e, at);
  // |sin u - sin w| = 2 cos((u + w)/2) sin(|u - w|/2).
  const double gap = 2.0 * cos_half_u_plus_w(e, at) * std::sin(0.5 * std::abs(diff));
  const double larger = std::max(e.sin_u, sin_w);
  return {std::min(e.sin_u, sin_w) / larger, gap / larger};
}

/// delta = (tau1 - tau2) / (1 - tau1 tau2) = -sin u sin w / (1 + cos u cos w), in (-1, 0], and
/// 1 + delta = 2 cos^2((u + w)/2) / (1 + cos u cos w) (accurate as delta -> -1, phi0 -> 0).
struct Delta {
  double delta;
  double one_plus_delta;
};
Delta eq31_delta(const EdgeAngles& e, const PointAngles& at) {
  const double denominator = 1.0 + e.cos_u * at.cos_w();
  const double c = cos_half_u_plus_w(e, at);
  return {-e.sin_u * at.sin_w() / denominator, 2.0 * c * c / denominator};
}

/// The bracket of Eq. 31, B = (pi - 2 phi0) cos(phi) + L(phi), in w = pi/2 - phi. With
/// ln|sin(phi + phi0)/sin(phi - phi0)| = 2 artanh(tau1), tau1 = min(tan u/tan w, tan w/tan u),
/// and ln|tan((phi + phi0)/2) tan((phi - phi0)/2)| = -2 artanh(tau2) (the sines' ratio):
///   B = 2u sin w + 2 cos w artanh(tau1) - 2 cos u artanh(tau2)
///     = 2u sin w + 2 cos w artanh(delta) + 2 (cos w - cos u) artanh(tau2),
///   delta = (tau1 - tau2) / (1 - tau1 tau2) = -sin u sin w / (1 + cos u cos w).
/// This regrouped form has no cancellation on the rounded edges, nor anywhere once u > pi/4.
double eq31_bracket_regrouped(const EdgeAngles& e, const PointAngles& at) {
  const double sin_w = at.sin_w();
  const double cos_w = at.cos_w();
  const Delta d = eq31_delta(e, at);
  const double diff = u_minus_w(e, at);
  double bracket = 2.0 * e.u * sin_w - 2.0 * cos_w * artanh_near_one(-d.delta, d.one_plus_delta);
  if (diff != 0.0) {  // at x = b the last term is 0 * ln(0) -> 0
    const SineRatio tau2 = sine_ratio(e, at);
    const double cos_w_minus_cos_u =
        2.0 * std::sin(0.5 * (e.u + at.w)) * std::sin(0.5 * diff);  // > 0 on the edges
    bracket += 2.0 * cos_w_minus_cos_u * artanh_near_one(tau2.tau, tau2.one_minus_tau);
  }
  return bracket;
}

/// The same bracket on the flat face when u <= pi/4, where the form above cancels from O(u) to
/// O(u^3): with artanh(t) = t + R(t),
///   B = -2 (sin u - u cos u) sin w / cos u + 2 tan u sin^2 u / sin w
///       + 2 cos w (R(delta) + delta tau1 tau2) + 2 (cos w - cos u) R(tau2),
/// tau1 = sin u cos w / (cos u sin w), tau2 = sin u / sin w: the second term is positive and the
/// others negative, the sum at least a third of the second term.
double eq31_bracket_flat_small_u(const EdgeAngles& e, const PointAngles& at) {
  const double sin_w = at.sin_w();
  const double cos_w = at.cos_w();
  const double tan_u = e.sin_u / e.cos_u;
  const Delta d = eq31_delta(e, at);
  const double tau1 = e.sin_u * cos_w / (e.cos_u * sin_w);
  const SineRatio tau2 = sine_ratio(e, at);
  const double cos_w_minus_cos_u = -2.0 * std::sin(0.5 * (e.u + at.w)) *
                                   std::sin(-0.5 * u_minus_w(e, at));  // < 0 on the flat face
  return -2.0 * sin_minus_t_cos_t(e.u) * sin_w / e.cos_u + 2.0 * tan_u * e.sin_u * e.sin_u / sin_w +
         2.0 * cos_w *
             (artanh_minus_identity(d.delta, d.one_plus_delta) + d.delta * tau1 * tau2.tau) +
         2.0 * cos_w_minus_cos_u * artanh_minus_identity(tau2.tau, tau2.one_minus_tau);
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

/// The root of an increasing f in [lo_limit, hi_limit] (f(lo_limit) <= 0 <= f(hi_limit)),
/// bracketed around `guess` first so that Brent starts within a factor of a few of it.
template <typename F>
double increasing_root(F f, double guess, double lo_limit, double hi_limit) {
  double lo = std::clamp(0.5 * guess, lo_limit, hi_limit);
  double hi = std::clamp(2.0 * guess, lo_limit, hi_limit);
  while (lo > lo_limit && f(lo) > 0.0)
    lo = std::max(0.25 * lo, lo_limit);
  while (hi < hi_limit && f(hi) < 0.0)
    hi = std::min(4.0 * hi, hi_limit);
  if (f(lo) == 0.0)
    return lo;
  if (f(hi) == 0.0)
    return hi;
  return brent_root(f, lo, hi);
}

void require_contact(const char* where, const SteuermannContact& contact) {
  require_positive(where, "flat half-width b", contact.b);
  require_positive(where, "load P", contact.P);
  const double u = contact.half_pi_minus_phi0;
  if (!(u > 0.0 && u <= 0.5 * kPi)) {  // u rounds to pi/2 when phi0 < 1e-16
    throw InvalidInput(std::string(where) + ": pi/2 - phi0 must lie in (0, pi/2) (got " +
                       format_value(u) + ")");
  }
  if (!(contact.phi0 > 0.0) || !(std::abs(u + contact.phi0 - 0.5 * kPi) <= 1e-15)) {
    throw InvalidInput(std::string(where) + ": phi0 = " + format_value(contact.phi0) +
                       " and pi/2 - phi0 = " + format_value(u) + " do not add up to pi/2");
  }
  require_positive(where, "contact half-width a", contact.contact_half_width_a);
}

/// The dimensionless groups of a punch but its load: lambda = 2 factor rho (P / b) / E.
struct Groups {
  double edge_ratio;  ///< rho = r_e / b
  double factor;      ///< 1 - nu^2, or 1 (Eq32Factor)
};

/// Validates every parameter of the punch but its load.
Groups punch_groups(const SteuermannPunch& punch) {
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
  const double rho = punch.r_e / punch.b;
  if (!(rho >= kMinEdgeRatio && rho <= kMaxEdgeRatio)) {
    throw InvalidInput(std::string(kWhere) +
                       ": edge radius over flat half-width r_e/b = " + format_value(rho) +
                       " outside the oracle's domain [1e-100, 1e100] (below: a sharp corner, "
                       "Sadowsky; above: a cylinder, Hertz)");
  }
  const double factor =
      punch.eq32_factor == Eq32Factor::kWithOneMinusNu2 ? 1.0 - punch.nu * punch.nu : 1.0;
  return {rho, factor};
}

/// The contact's limit, a = b + r_e: cos(u_max) = sin(phi0_min) = 1 / (1 + rho).
EdgeAngles max_edge_angles(double rho) {
  const double tan_u_max = std::sqrt(rho) * std::sqrt(2.0 + rho);  // (rho (2 + rho))^(1/2)
  const double u_max = std::atan(tan_u_max);
  const double phi0_min = std::atan2(1.0, tan_u_max);
  return edge_angles(u_max, phi0_min);
}

/// Solves Eq. 32 for lambda < rhs at the limit `max`: in u = pi/2 - phi0 for light loads
/// (u <= pi/4, lambda ~ 2u^3/3), in phi0 for heavy ones (lambda ~ pi / (2 phi0^2)), so that the
/// smaller angle keeps its relative precision.
EdgeAngles solve_eq32(double lambda, const EdgeAngles& max) {
  const double rhs_at_quarter_pi = 0.5 * kPi - 1.0;
  if (max.small_u || lambda <= rhs_at_quarter_pi) {
    auto f = [lambda](double u) { return eq32_rhs(edge_angles(u, 0.5 * kPi - u)) - lambda; };
    const double u =
        increasing_root(f, std::cbrt(1.5 * lambda), 0.0, max.small_u ? max.u : kQuarterPi);
    return edge_angles(u, 0.5 * kPi - u);
  }
  // sin(phi0) = (D / (2 lambda))^(1/2), D = pi - 2 phi0 - sin(2 phi0): increasing in phi0.
  auto f = [lambda](double phi0) {
    return std::sin(phi0) - std::sqrt((kPi - 2.0 * phi0 - std::sin(2.0 * phi0)) / (2.0 * lambda));
  };
  const double phi0 = increasing_root(f, std::sqrt(0.5 * kPi / lambda), max.phi0, kQuarterPi);
  return edge_angles(0.5 * kPi - phi0, phi0);
}

/// The pressure at the angles of a point, (P/b) cos(u) (2/pi) B / D, on the flat face or not.
double pressure_at(const SteuermannContact& contact, const EdgeAngles& e, const PointAngles& at,
                   bool flat_face) {
  const double bracket =
      flat_face && e.small_u ? eq31_bracket_flat_small_u(e, at) : eq31_bracket_regrouped(e, at);
  const double pressure =
      contact.P / contact.b * e.cos_u * (2.0 / kPi) * (bracket / eq31_denominator(e));
  // Rounding can leave a tiny negative value next to x = a, where the pressure -> 0.
  return pressure > 0.0 ? pressure : 0.0;
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
  const Groups g = punch_groups(punch);
  require_positive("steuermann", "load P", punch.P);
  // lambda = 2 r_e (1 - nu^2) P / (b^2 E), as dimensionless groups: no spurious overflow.
  return 2.0 * g.factor * g.edge_ratio * (punch.P / punch.b / punch.E);
}

double steuermann_max_load(const SteuermannPunch& punch) {
  const Groups g = punch_groups(punch);
  // rhs(limit) / (lambda / P) = (D / 2) (1 + rho)^2 b E / (2 factor rho), in an order that
  // overflows only if the load itself does (+inf then).
  const EdgeAngles max = max_edge_angles(g.edge_ratio);
  const double one_plus_rho = 1.0 + g.edge_ratio;
  return 0.25 * eq31_denominator(max) / g.factor * one_plus_rho * (one_plus_rho / g.edge_ratio) *
         punch.b * punch.E;
}

SteuermannContact steuermann_contact(const SteuermannPunch& punch) {
  constexpr const char* kWhere = "steuermann_contact";
  const double lambda = steuermann_load_parameter(punch);
  const double P_over_b = punch.P / punch.b;
  if (!(lambda >= kMinLoadParameter) || !(P_over_b >= std::numeric_limits<double>::min())) {
    throw InvalidInput(std::string(kWhere) + ": load P = " + format_value(punch.P) +
                       " too light for the oracle: the load parameter of Eq. 32 is " +
                       format_value(lambda) +
                       " < 1e-300 or P/b underflows (the limit is Sadowsky's sharp punch)");
  }
  if (!std::isfinite(lambda) || !std::isfinite(P_over_b)) {
    throw InvalidInput(std::string(kWhere) + ": load P = " + format_value(punch.P) +
                       " out of floating-point range: the load parameter of Eq. 32 or P/b "
                       "overflows");
  }
  const EdgeAngles max = max_edge_angles(punch.r_e / punch.b);
  const double rhs_max = eq32_rhs(max);
  if (lambda > rhs_max) {
    throw InvalidInput(std::string(kWhere) + ": load P = " + format_value(punch.P) +
                       " would spread contact past the rounded edges (a > b + r_e = " +
                       format_value(punch.b + punch.r_e) +
                       "); the largest load is P = " + format_value(steuermann_max_load(punch)));
  }
  const EdgeAngles e = lambda == rhs_max ? max : solve_eq32(lambda, max);
  const double a = punch.b / e.cos_u;
  if (!std::isfinite(a)) {
    throw InvalidInput(std::string(kWhere) +
                       ": the contact half-width a = b / sin(phi0) = " + format_value(punch.b) +
                       " / " + format_value(e.cos_u) + " is out of floating-point range");
  }
  return {
      .b = punch.b,
      .P = punch.P,
      .phi0 = e.phi0,
      .half_pi_minus_phi0 = e.u,
      .contact_half_width_a = a,
  };
}

double steuermann_pressure(const SteuermannContact& contact, double x) {
  constexpr const char* kWhere = "steuermann_pressure";
  require_contact(kWhere, contact);
  require_finite(kWhere, "position x", x);
  const EdgeAngles e = edge_angles(contact.half_pi_minus_phi0, contact.phi0);
  const double a = contact.contact_half_width_a;
  const double b = contact.b;
  const double s = std::abs(x);
  // a - x from a - b = b (1 - cos u) / cos u, exact to rounding even when a rounds to b
  // (u < 1e-8), and b - x, exact next to b.
  const double sin_half_u = std::sin(0.5 * e.u);
  const double a_minus_b =
      e.small_u ? b * (2.0 * sin_half_u * sin_half_u) / e.cos_u : b * (1.0 - e.cos_u) / e.cos_u;
  const double a_minus_x = a_minus_b - (s - b);
  if (!(a_minus_x > 0.0) || (s >= a && s != b))  // a may round to b when u < 1e-8
    return 0.0;
  PointAngles at{e.u, e.phi0};  // x = b
  if (s != b) {
    if (s <= 0.5 * a) {
      at.phi = std::asin(s / a);
      at.w = 0.5 * kPi - at.phi;
    } else {  // 1 - cos(w) = (a - x) / a
      at.w = 2.0 * std::asin(std::sqrt(0.5 * a_minus_x / a));
      at.phi = 0.5 * kPi - at.w;
    }
    // Keep each point on its side of x = b, whatever the rounding of the angles.
    if ((s < b) != (at.w > e.u))
      at = {e.u, e.phi0};
  }
  return pressure_at(contact, e, at, s < b);
}

SteuermannPeak steuermann_peak(const SteuermannContact& contact) {
  constexpr const char* kWhere = "steuermann_peak";
  require_contact(kWhere, contact);
  const EdgeAngles e = edge_angles(contact.half_pi_minus_phi0, contact.phi0);
  const double u = e.u;
  // dp/dphi ~ h(psi), psi = phi - phi0 in (0, u], w = u - psi:
  //   h = sin(w) ln(sin(u + w) / sin(psi)) - 2u cos(w),  sin(u + w) = sin(phi + phi0),
  // +inf at psi -> 0+, -2u at psi = u (phi = pi/2, x = a). Each sine is taken from the
  // smaller of its complementary angles, so that phi0 -> 0 (heavy loads) keeps its digits.
  auto angles = [&e](double psi) { return PointAngles{e.u - psi, e.phi0 + psi}; };
  // sin(u + w) / sin(u - w) = 1 + 2 cos(u) sin(w) / sin(psi): log1p keeps the digits when the
  // ratio is close to 1 (phi0 -> 0).
  auto h = [&e, &angles](double psi) {
    const PointAngles at = angles(psi);
    const double sin_w = at.sin_w();
    return sin_w * std::log1p(2.0 * e.cos_u * sin_w / std::sin(psi)) - 2.0 * e.u * at.cos_w();
  };
  double psi_lo = 1e-6 * u;
  while (!(h(psi_lo) > 0.0)) {
    psi_lo *= 1e-6;
    if (!(psi_lo > 0.0))
      throw InvalidInput(std::string(kWhere) + ": cannot bracket the peak");
  }
  const double psi = brent_root(h, psi_lo, u);
  const PointAngles at = angles(psi);
  const double x_peak =
      contact.contact_half_width_a * (at.w <= kQuarterPi ? std::cos(at.w) : std::sin(at.phi));
  return {
      .peak_pressure = pressure_at(contact, e, at, false),
      .x_peak = x_peak,
      .phi_peak = at.phi,
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
