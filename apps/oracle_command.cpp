// `contact-suite oracle NAME [options]`: one exact solution, one JSON object on stdout.
// `contact-suite oracle table [--json]`: the study's exact values as the oracles compute them.
//
// Every handler validates through the oracles (InvalidInput, a std::invalid_argument) or throws
// UsageError; main() turns both into one line on stderr and exit code 2. Nothing is printed
// unless every number of the answer is finite.

#include "apps/oracle_command.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "apps/finite_number.hpp"
#include "apps/usage_error.hpp"
#include "oracles/boussinesq.hpp"
#include "oracles/flat_punch.hpp"
#include "oracles/hertz_axi.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/patch_test.hpp"
#include "oracles/steuermann.hpp"
#include "oracles/strip_load.hpp"

namespace cs::apps {
namespace {

using Json = nlohmann::ordered_json;
namespace o = cs::oracles;

// ---------------------------------------------------------------------------------------------
// Output and parsing helpers

/// Throws UsageError if any number in `value` is NaN or infinite (inputs beyond what double
/// precision can answer), so that no such value is ever printed.
void require_all_finite(const Json& value, const std::string& path) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    throw UsageError("the result " + path +
                     " is not finite: the inputs are out of floating-point range");
  }
  if (value.is_object()) {
    for (const auto& [key, item] : value.items())
      require_all_finite(item, key);
  } else if (value.is_array()) {
    for (const auto& item : value)
      require_all_finite(item, path);
  }
}

/// Prints one JSON object on one line of stdout, every double to full (round-trip) precision.
void print_json(const Json& answer) {
  require_all_finite(answer, "");
  const std::string text = answer.dump();
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);
}

/// One number of an option value, whole text consumed.
double parse_number(std::string_view text, std::string_view option) {
  double value = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty() && *first == '+')
    ++first;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last) {
    throw UsageError(fmt::format("{}: '{}' is not a number", option, text));
  }
  return value;
}

/// "A,B" -> {A, B}.
std::pair<double, double> parse_pair(const std::string& text, std::string_view option,
                                     std::string_view names) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    throw UsageError(fmt::format("{}: expected {} (two numbers separated by a comma), got '{}'",
                                 option, names, text));
  }
  return {parse_number(std::string_view(text).substr(0, comma), option),
          parse_number(std::string_view(text).substr(comma + 1), option)};
}

/// A required numeric option.
CLI::Option* add_number(CLI::App* app, const std::string& name, double& value,
                        const std::string& help) {
  return app->add_option(name, value, help)->required()->check(finite_number());
}

// ---------------------------------------------------------------------------------------------
// Hertz

struct HertzOptions {
  double R = 0.0;
  double E = 0.0;
  double nu = 0.0;
  double P = 0.0;
};

void add_hertz_options(CLI::App* sub, HertzOptions& opt, const char* load_help) {
  add_number(sub, "--R", opt.R, "indenter radius R (> 0)");
  add_number(sub, "--E", opt.E, "Young's modulus E of the half-space (> 0)");
  add_number(sub, "--nu", opt.nu, "Poisson's ratio nu of the half-space, in [0, 0.5)");
  add_number(sub, "--load", opt.P, load_help);
}

void add_hertz_plane(CLI::App& oracle) {
  auto opt = std::make_shared<HertzOptions>();
  auto* sub = oracle.add_subcommand(
      "hertz-plane",
      "Hertz, rigid cylinder on a half-space, plane strain (Eqs. 15-16): half-width a, mean "
      "pressure p_mean = P/(2a), peak pressure p_max = 4p/pi");
  add_hertz_options(sub, *opt, "load P per unit length (> 0)");
  sub->callback([opt] {
    const o::HertzPlaneContact c = o::hertz_plane_contact({opt->R, opt->E, opt->nu, opt->P});
    print_json({{"a", c.contact_half_width_a}, {"p_mean", c.p_mean}, {"p_max", c.p_max}});
  });
}

void add_hertz_axi(CLI::App& oracle) {
  auto opt = std::make_shared<HertzOptions>();
  auto* sub = oracle.add_subcommand(
      "hertz-axi",
      "Hertz, rigid sphere on a half-space (Eqs. 22-23): contact radius a, mean pressure "
      "p_mean = P/(pi a^2), peak pressure p_max = 3p/2");
  add_hertz_options(sub, *opt, "total load P (> 0)");
  sub->callback([opt] {
    const o::HertzAxiContact c = o::hertz_axi_contact({opt->R, opt->E, opt->nu, opt->P});
    print_json({{"a", c.contact_radius_a}, {"p_mean", c.p_mean}, {"p_max", c.p_max}});
  });
}

// ---------------------------------------------------------------------------------------------
// Interior fields

struct FieldOptions {
  double a = 0.0;
  double p = 0.0;
  std::string at;
};

Json plane_stress_json(const o::PlaneStress& s) {
  return {{"sigma_x", s.sigma_x}, {"sigma_z", s.sigma_z}, {"tau_xz", s.tau_xz}};
}

void add_mcewen(CLI::App& oracle) {
  auto opt = std::make_shared<FieldOptions>();
  auto* sub = oracle.add_subcommand(
      "mcewen",
      "McEwen interior stress of plane-strain Hertz contact (Eqs. 11-12) at (X, Z), Z >= 0 into "
      "the body: sigma_x, sigma_z, tau_xz (compression negative)");
  add_number(sub, "--a", opt->a, "contact half-width a (> 0)");
  add_number(sub, "--p", opt->p, "mean contact pressure p = P/(2a) (> 0)");
  sub->add_option("--at", opt->at, "the point X,Z (Z >= 0; write --at=-1,2 for negative X)")
      ->required();
  sub->callback([opt] {
    const auto [x, z] = parse_pair(opt->at, "--at", "X,Z");
    print_json(plane_stress_json(o::mcewen_stress({opt->a, opt->p}, {x, z})));
  });
}

void add_strip(CLI::App& oracle) {
  auto opt = std::make_shared<FieldOptions>();
  auto* sub = oracle.add_subcommand(
      "strip",
      "Uniform pressure p on the strip |x| < a of a half-space (Eqs. 35-36) at (X, Z): "
      "sigma_x, sigma_z, tau_xz (compression negative)");
  add_number(sub, "--a", opt->a, "strip half-width a (> 0)");
  add_number(sub, "--p", opt->p, "uniform pressure p (> 0)");
  sub->add_option("--at", opt->at, "the point X,Z (Z >= 0; write --at=-1,2 for negative X)")
      ->required();
  sub->callback([opt] {
    const auto [x, z] = parse_pair(opt->at, "--at", "X,Z");
    print_json(plane_stress_json(o::strip_load_stress({opt->a, opt->p}, {x, z})));
  });
}

void add_boussinesq(CLI::App& oracle) {
  struct Options {
    double P = 0.0;
    double nu = 0.0;
    std::string at;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = oracle.add_subcommand(
      "boussinesq",
      "Boussinesq point load on a half-space (Eqs. 18-19) at (R, Z): sigma_r, sigma_z, "
      "sigma_theta, tau_rz (compression negative)");
  add_number(sub, "--load", opt->P, "point load P (> 0)");
  add_number(sub, "--nu", opt->nu, "Poisson's ratio nu, in [0, 0.5)");
  sub->add_option("--at", opt->at, "the point R,Z (R >= 0, Z >= 0, not the load point 0,0)")
      ->required();
  sub->callback([opt] {
    const auto [r, z] = parse_pair(opt->at, "--at", "R,Z");
    const o::AxiStress s = o::boussinesq_stress({opt->P, opt->nu}, {r, z});
    print_json({{"sigma_r", s.sigma_r},
                {"sigma_z", s.sigma_z},
                {"sigma_theta", s.sigma_theta},
                {"tau_rz", s.tau_rz}});
  });
}

// ---------------------------------------------------------------------------------------------
// Punches

/// --eq32-factor values.
constexpr const char* kWithFactor = "with";
constexpr const char* kWithoutFactor = "without";

o::Eq32Factor parse_eq32_factor(const std::string& text) {
  if (text == kWithFactor)
    return o::Eq32Factor::kWithOneMinusNu2;
  if (text == kWithoutFactor)
    return o::Eq32Factor::kWithoutOneMinusNu2;
  throw UsageError(fmt::format("--eq32-factor: expected '{}' or '{}', got '{}'", kWithFactor,
                               kWithoutFactor, text));
}

void add_steuermann(CLI::App& oracle) {
  struct Options {
    double b = 0.0;
    double r_e = 0.0;
    double P = 0.0;
    double E = 0.0;
    double nu = 0.0;
    std::string factor = kWithFactor;
    std::vector<double> at;
  };
  auto opt = std::make_shared<Options>();
  auto* sub = oracle.add_subcommand(
      "steuermann",
      "Steuermann rounded flat punch, plane strain (Eqs. 31-32): contact half-width a, phi0, "
      "peak_pressure and x_peak, and the pressure at X if asked");
  add_number(sub, "--b", opt->b, "half-width b of the flat face (> 0)");
  add_number(sub, "--re", opt->r_e, "edge radius r_e (> 0)");
  add_number(sub, "--load", opt->P, "load P per unit length (> 0)");
  add_number(sub, "--E", opt->E, "Young's modulus E of the half-space (> 0)");
  add_number(sub, "--nu", opt->nu, "Poisson's ratio nu of the half-space, in [0, 0.5)");
  sub->add_option("--eq32-factor", opt->factor,
                  "'with': Eq. 32 carries (1 - nu^2), plane strain, physically consistent "
                  "(default); 'without': drops it, which reproduces the study's printed "
                  "9.9773 and 13.1753")
      ->check(CLI::IsMember({kWithFactor, kWithoutFactor}))
      ->capture_default_str();
  sub->add_option("--at", opt->at, "a position X at which to give the contact pressure")
      ->check(finite_number())
      ->expected(1);
  sub->callback([opt] {
    const o::SteuermannPunch punch{opt->b, opt->r_e, opt->P,
                                   opt->E, opt->nu,  parse_eq32_factor(opt->factor)};
    const o::SteuermannContact c = o::steuermann_contact(punch);
    const o::SteuermannPeak peak = o::steuermann_peak(c);
    const double p_study = o::steuermann_study_pressure(punch);
    Json answer{{"a", c.contact_half_width_a},
                {"phi0", c.phi0},
                {"peak_pressure", peak.peak_pressure},
                {"x_peak", peak.x_peak}};
    if (!opt->at.empty())
      answer["pressure"] = o::steuermann_pressure(c, opt->at.front());
    answer["eq32_factor"] = std::string(o::to_string(punch.eq32_factor));
    answer["one_minus_nu2_in_eq32"] = punch.eq32_factor == o::Eq32Factor::kWithOneMinusNu2;
    answer["p_study"] = p_study;
    answer["peak_over_p_study"] = peak.peak_pressure / p_study;
    answer["max_load"] = o::steuermann_max_load(punch);
    print_json(answer);
  });
}

struct PunchOptions {
  double a = 0.0;
  double P = 0.0;
  double at = 0.0;
};

void add_sadowsky(CLI::App& oracle) {
  auto opt = std::make_shared<PunchOptions>();
  auto* sub = oracle.add_subcommand(
      "sadowsky",
      "Sadowsky flat strip punch, plane strain (Eq. 39): contact pressure at X (unbounded at "
      "|X| = a)");
  add_number(sub, "--a", opt->a, "punch half-width a (> 0)");
  add_number(sub, "--load", opt->P, "load P per unit length (> 0)");
  add_number(sub, "--at", opt->at, "position X (|X| != a)");
  sub->callback([opt] {
    const o::SadowskyPunch punch{opt->a, opt->P};
    const double pressure = o::sadowsky_pressure(punch, opt->at);
    print_json({{"pressure", pressure}, {"p_mean", o::sadowsky_mean_pressure(punch)}});
  });
}

void add_harding_sneddon(CLI::App& oracle) {
  auto opt = std::make_shared<PunchOptions>();
  auto* sub = oracle.add_subcommand(
      "harding-sneddon",
      "Harding-Sneddon flat circular punch (Eq. 45): contact pressure at radius R (unbounded at "
      "R = a)");
  add_number(sub, "--a", opt->a, "punch radius a (> 0)");
  add_number(sub, "--load", opt->P, "total load P (> 0)");
  add_number(sub, "--at", opt->at, "radius R (>= 0, != a)");
  sub->callback([opt] {
    const o::HardingSneddonPunch punch{opt->a, opt->P};
    const double pressure = o::harding_sneddon_pressure(punch, opt->at);
    print_json({{"pressure", pressure}, {"p_mean", o::harding_sneddon_mean_pressure(punch)}});
  });
}

// ---------------------------------------------------------------------------------------------
// The reference table

/// The study's printed exact values (Appendix), shown beside the oracles' values.
constexpr double kStudyPatch = 1.0000;
constexpr double kStudyHertzPlane = 1.2732;
constexpr double kStudyHertzAxi = 1.5000;

struct SteuermannStudyRow {
  const char* re_over_b_text;
  double re_over_b;
  double study_printed;  ///< the Appendix's "exact value from Equation (31)"
};
constexpr SteuermannStudyRow kSteuermannRows[] = {
    {"1", 1.0, 9.9773}, {"1/3", 1.0 / 3.0, 10.9571}, {"1/7", 1.0 / 7.0, 13.1753}};
constexpr double kSteuermannNu = 0.25;
constexpr double kSteuermannPOverE = 1e-3;

struct SteuermannRow {
  const SteuermannStudyRow* study;
  o::Eq32Factor factor;
  double a_over_b;
  double phi0;
  double x_peak_over_b;
  double peak_over_p;
};

struct ReferenceValues {
  double patch;
  double hertz_plane_sigma_c;
  double hertz_plane_sigma_h;
  double hertz_axi_sigma_c;
  std::vector<SteuermannRow> steuermann;
};

ReferenceValues compute_reference_values() {
  ReferenceValues v{};
  const double p = 1.0;
  v.patch = -o::patch_test_plane_stress({p}, {0.0, 0.0}).sigma_z / p;
  // Normalized values do not depend on R, E, nu, P: any admissible set does.
  const o::HertzPlaneContact hp = o::hertz_plane_contact({1.0, 1.0, kSteuermannNu, 1e-3});
  const o::PlaneStress centre = o::mcewen_stress({hp.contact_half_width_a, hp.p_mean}, {0.0, 0.0});
  v.hertz_plane_sigma_c = -centre.sigma_z / hp.p_mean;
  v.hertz_plane_sigma_h = -centre.sigma_x / hp.p_mean;
  const o::HertzAxiContact ha = o::hertz_axi_contact({1.0, 1.0, kSteuermannNu, 1e-3});
  v.hertz_axi_sigma_c = o::hertz_axi_pressure(ha, 0.0) / ha.p_mean;
  for (const SteuermannStudyRow& row : kSteuermannRows) {
    for (const o::Eq32Factor factor :
         {o::Eq32Factor::kWithOneMinusNu2, o::Eq32Factor::kWithoutOneMinusNu2}) {
      const double b = 1.0;
      const o::SteuermannPunch punch = o::steuermann_study_punch(
          {b, row.re_over_b * b, 1.0, kSteuermannNu, kSteuermannPOverE, factor});
      const o::SteuermannContact c = o::steuermann_contact(punch);
      const o::SteuermannPeak peak = o::steuermann_peak(c);
      v.steuermann.push_back({&row, factor, c.contact_half_width_a / b, c.phi0, peak.x_peak / b,
                              peak.peak_pressure / o::steuermann_study_pressure(punch)});
    }
  }
  return v;
}

const char* factor_option(o::Eq32Factor factor) {
  return factor == o::Eq32Factor::kWithOneMinusNu2 ? kWithFactor : kWithoutFactor;
}

Json reference_json(const ReferenceValues& v) {
  Json steuermann_cases = Json::array();
  for (const SteuermannRow& row : v.steuermann) {
    steuermann_cases.push_back(
        {{"re_over_b", row.study->re_over_b},
         {"eq32_factor", std::string(o::to_string(row.factor))},
         {"one_minus_nu2_in_eq32", row.factor == o::Eq32Factor::kWithOneMinusNu2},
         {"a_over_b", row.a_over_b},
         {"phi0", row.phi0},
         {"x_peak_over_b", row.x_peak_over_b},
         {"peak_over_p", row.peak_over_p},
         {"study_printed", row.study->study_printed}});
  }
  return {
      {"patch_test",
       {{"equation", "6, 8"}, {"sigma_z_over_p", v.patch}, {"study_printed", kStudyPatch}}},
      {"hertz_plane",
       {{"equation", "15"},
        {"sigma_c", v.hertz_plane_sigma_c},
        {"sigma_h", v.hertz_plane_sigma_h},
        {"study_printed", kStudyHertzPlane}}},
      {"hertz_axi",
       {{"equation", "22"}, {"sigma_c", v.hertz_axi_sigma_c}, {"study_printed", kStudyHertzAxi}}},
      {"steuermann",
       {{"equation", "31-32"},
        {"nu", kSteuermannNu},
        {"p_over_E", kSteuermannPOverE},
        {"p", "P / (2 (b + r_e))"},
        {"grade_against", "with (1 - nu^2)"},
        {"cases", steuermann_cases}}},
      {"flat_punch_plane", {{"equation", "39"}, {"sigma_c_star", "unbounded at x = a"}}},
      {"flat_punch_axi", {{"equation", "45"}, {"sigma_c_star", "unbounded at r = a"}}},
  };
}

std::string reference_text(const ReferenceValues& v) {
  std::string out;
  auto line = [&out](const std::string& text) { out += text + "\n"; };
  line("Exact values of the study's test problems, as computed by contact-suite's oracles");
  line("(normalized stresses: compression reported positive; 'study' is the Appendix's value)");
  line("");
  line(fmt::format("{:<36}{:<22}{:>12}{:>10}", "problem", "quantity", "oracle", "study"));
  line(fmt::format("{:<36}{:<22}{:>12.6f}{:>10.4f}", "P   patch tests (Eqs. 6, 8)", "-sigma_z / p",
                   v.patch, kStudyPatch));
  line(fmt::format("{:<36}{:<22}{:>12.6f}{:>10.4f}", "H_p Hertz cylinder (Eq. 15)",
                   "-sigma_z(0,0) / p", v.hertz_plane_sigma_c, kStudyHertzPlane));
  line(fmt::format("{:<36}{:<22}{:>12.6f}{:>10.4f}", "", "-sigma_x(0,0) / p", v.hertz_plane_sigma_h,
                   kStudyHertzPlane));
  line(fmt::format("{:<36}{:<22}{:>12.6f}{:>10.4f}", "H_a Hertz sphere (Eq. 22)",
                   "-sigma_z(0,0) / p", v.hertz_axi_sigma_c, kStudyHertzAxi));
  line(fmt::format("{:<36}{:<22}{:>12}{:>10}", "F_p flat strip punch (Eq. 39)", "-sigma_z(a,0) / p",
                   "-> inf", "-> inf"));
  line(fmt::format("{:<36}{:<22}{:>12}{:>10}", "F_a flat circular punch (Eq. 45)",
                   "-sigma_z(a,0) / p", "-> inf", "-> inf"));
  line("");
  line("S   Steuermann rounded punch (Eqs. 31-32): -sigma_z max / p, p = P / (2 (b + r_e)),");
  line("    nu = 1/4, p/E = 1/1000");
  line(fmt::format("    {:<7}{:<22}{:>10}{:>12}{:>12}{:>14}{:>10}", "r_e/b", "Eq. 32", "a/b",
                   "phi0", "x_peak/b", "oracle", "study"));
  for (const SteuermannRow& row : v.steuermann) {
    line(fmt::format("    {:<7}{:<22}{:>10.6f}{:>12.8f}{:>12.8f}{:>14.6f}{:>10.4f}",
                     row.study->re_over_b_text, std::string(o::to_string(row.factor)), row.a_over_b,
                     row.phi0, row.x_peak_over_b, row.peak_over_p, row.study->study_printed));
  }
  line("");
  line("    Grade against 'with (1 - nu^2)' (plane strain, physically consistent). The study's");
  line("    9.9773 and 13.1753 follow from 'without'; its 10.9571 (r_e/b = 1/3) from neither.");
  line(
      fmt::format("    One case: contact-suite oracle steuermann --b 1 --re 1 --load 0.004 --E 1 "
                  "--nu 0.25 --eq32-factor {}",
                  factor_option(o::Eq32Factor::kWithOneMinusNu2)));
  return out;
}

void add_table(CLI::App& oracle) {
  auto json = std::make_shared<bool>(false);
  auto* sub = oracle.add_subcommand(
      "table",
      "The reference table: the study's exact values (Hertz 4/pi and 3/2, Steuermann with and "
      "without (1 - nu^2), flat punch -> infinity) as the oracles compute them");
  sub->add_flag("--json", *json, "print the table as one JSON object instead of text");
  sub->callback([json] {
    const ReferenceValues values = compute_reference_values();
    if (*json) {
      print_json(reference_json(values));
    } else {
      const std::string text = reference_text(values);
      std::fwrite(text.data(), 1, text.size(), stdout);
      std::fflush(stdout);
    }
  });
}

}  // namespace

void add_oracle_command(CLI::App& app) {
  auto* oracle = app.add_subcommand(
      "oracle",
      "Evaluate one exact solution and print one JSON object: hertz-plane, hertz-axi, mcewen, "
      "boussinesq, strip, steuermann, sadowsky, harding-sneddon; or print the reference table");
  // At most one oracle; naming none is reported below, with the names to choose from (an
  // unknown name is an unexpected argument, reported by CLI11 with the name).
  oracle->require_subcommand(0, 1);
  oracle->callback([oracle] {
    if (oracle->get_subcommands().empty()) {
      throw UsageError(
          "oracle: name one of hertz-plane, hertz-axi, mcewen, boussinesq, strip, steuermann, "
          "sadowsky, harding-sneddon, table (see contact-suite oracle --help)");
    }
  });
  add_hertz_plane(*oracle);
  add_hertz_axi(*oracle);
  add_mcewen(*oracle);
  add_boussinesq(*oracle);
  add_strip(*oracle);
  add_steuermann(*oracle);
  add_sadowsky(*oracle);
  add_harding_sneddon(*oracle);
  add_table(*oracle);
}

}  // namespace cs::apps
