// Every oracle refuses input it cannot answer with InvalidInput (a std::invalid_argument, so
// the command line maps it to exit code 2), on one line naming the parameter and its value.

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "oracles/boussinesq.hpp"
#include "oracles/flamant.hpp"
#include "oracles/flat_punch.hpp"
#include "oracles/hertz_axi.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/invalid_input.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/patch_test.hpp"
#include "oracles/steuermann.hpp"
#include "oracles/strip_load.hpp"

namespace cs::oracles {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct BadCall {
  std::string label;
  std::function<void()> call;
  std::vector<std::string> message_mentions;  ///< substrings the message must contain
};

std::vector<BadCall> bad_calls() {
  const HertzCylinder cylinder{.R = 1.0, .E = 1.0, .nu = 0.3, .P = 1.0};
  const HertzSphere sphere{.R = 1.0, .E = 1.0, .nu = 0.3, .P = 1.0};
  const SteuermannPunch punch{.b = 1.0, .r_e = 1.0, .P = 1e-3, .E = 1.0, .nu = 0.25};
  const SteuermannContact contact = steuermann_contact(punch);
  auto cyl = [&](auto edit) {
    HertzCylinder c = cylinder;
    edit(c);
    return [c] { (void)hertz_plane_contact(c); };
  };
  auto sph = [&](auto edit) {
    HertzSphere s = sphere;
    edit(s);
    return [s] { (void)hertz_axi_contact(s); };
  };
  auto steu = [&](auto edit) {
    SteuermannPunch s = punch;
    edit(s);
    return [s] { (void)steuermann_contact(s); };
  };
  return {
      {"hertz plane R = 0", cyl([](auto& c) { c.R = 0.0; }), {"radius R", "0"}},
      {"hertz plane E < 0", cyl([](auto& c) { c.E = -2.0; }), {"Young's modulus E", "-2"}},
      {"hertz plane nu = 0.5", cyl([](auto& c) { c.nu = 0.5; }), {"nu", "0.5"}},
      {"hertz plane nu < 0", cyl([](auto& c) { c.nu = -0.1; }), {"nu", "-0.1"}},
      {"hertz plane P = nan", cyl([](auto& c) { c.P = kNan; }), {"load", "nan"}},
      {"hertz plane P = inf", cyl([](auto& c) { c.P = kInf; }), {"load", "inf"}},
      {"hertz plane overflow",
       cyl([](auto& c) { c.R = 1e300, c.P = 1e300, c.E = 1e-300; }),
       {"range"}},
      {"hertz plane pressure at nan",
       [] {
         (void)hertz_plane_pressure({1.0, 1.0, 1.0}, kNan);
       },
       {"position x", "nan"}},
      {"hertz axi R < 0", sph([](auto& s) { s.R = -1.0; }), {"radius R", "-1"}},
      {"hertz axi nu = 0.7", sph([](auto& s) { s.nu = 0.7; }), {"nu", "0.7"}},
      {"hertz axi P = 0", sph([](auto& s) { s.P = 0.0; }), {"load P", "0"}},
      {"hertz axi pressure r < 0",
       [] {
         (void)hertz_axi_pressure({1.0, 1.0, 1.5}, -0.5);
       },
       {"radius r", "-0.5"}},
      {"mcewen z < 0",
       [] {
         (void)mcewen_stress({1.0, 1.0}, {0.0, -0.1});
       },
       {"z", "-0.1"}},
      {"mcewen a = 0",
       [] {
         (void)mcewen_stress({0.0, 1.0}, {0.0, 0.1});
       },
       {"half-width a"}},
      {"mcewen p < 0",
       [] {
         (void)mcewen_stress({1.0, -3.0}, {0.0, 0.1});
       },
       {"pressure p", "-3"}},
      {"boussinesq z < 0",
       [] {
         (void)boussinesq_stress({1.0, 0.3}, {1.0, -1e-9});
       },
       {"z", "-1e-09"}},
      {"boussinesq r < 0",
       [] {
         (void)boussinesq_stress({1.0, 0.3}, {-1.0, 1.0});
       },
       {"radius r"}},
      {"boussinesq load point",
       [] {
         (void)boussinesq_stress({1.0, 0.3}, {0.0, 0.0});
       },
       {"load point"}},
      {"boussinesq nu = 0.5",
       [] {
         (void)boussinesq_stress({1.0, 0.5}, {1.0, 1.0});
       },
       {"nu"}},
      {"boussinesq P = 0",
       [] {
         (void)boussinesq_stress({0.0, 0.3}, {1.0, 1.0});
       },
       {"load P"}},
      {"flamant load point",
       [] {
         (void)flamant_stress({1.0}, {0.0, 0.0});
       },
       {"load point"}},
      {"flamant z < 0",
       [] {
         (void)flamant_stress({1.0}, {1.0, -2.0});
       },
       {"z", "-2"}},
      {"flamant P < 0",
       [] {
         (void)flamant_stress({-1.0}, {1.0, 2.0});
       },
       {"P", "-1"}},
      {"strip z < 0",
       [] {
         (void)strip_load_stress({1.0, 1.0}, {0.0, -1.0});
       },
       {"z"}},
      {"strip edge",
       [] {
         (void)strip_load_stress({1.0, 1.0}, {-1.0, 0.0});
       },
       {"edge", "-1"}},
      {"strip a < 0",
       [] {
         (void)strip_load_stress({-1.0, 1.0}, {0.0, 1.0});
       },
       {"half-width a"}},
      {"strip x = inf",
       [] {
         (void)strip_load_stress({1.0, 1.0}, {kInf, 1.0});
       },
       {"x", "inf"}},
      {"steuermann b = 0", steu([](auto& s) { s.b = 0.0; }), {"flat half-width b"}},
      {"steuermann r_e < 0", steu([](auto& s) { s.r_e = -1.0; }), {"edge radius r_e", "-1"}},
      {"steuermann E = 0", steu([](auto& s) { s.E = 0.0; }), {"Young's modulus E"}},
      {"steuermann nu = 0.5", steu([](auto& s) { s.nu = 0.5; }), {"nu", "0.5"}},
      {"steuermann P = 0", steu([](auto& s) { s.P = 0.0; }), {"load P"}},
      {"steuermann overload", steu([](auto& s) { s.P = 10.0; }), {"rounded edges", "10"}},
      {"steuermann bad factor",
       steu([](auto& s) { s.eq32_factor = static_cast<Eq32Factor>(7); }),
       {"Eq32Factor"}},
      {"steuermann pressure at nan",
       [contact] { (void)steuermann_pressure(contact, kNan); },
       {"position x"}},
      {"steuermann pressure, forged contact",
       [contact] {
         SteuermannContact forged = contact;
         forged.half_pi_minus_phi0 = -0.1;
         (void)steuermann_pressure(forged, 0.0);
       },
       {"phi0"}},
      {"steuermann study p/E = 0",
       [] {
         (void)steuermann_study_punch({1.0, 1.0, 1.0, 0.25, 0.0});
       },
       {"p/E"}},
      {"sadowsky edge",
       [] {
         (void)sadowsky_pressure({2.0, 1.0}, 2.0);
       },
       {"edge", "2"}},
      {"sadowsky a = 0",
       [] {
         (void)sadowsky_pressure({0.0, 1.0}, 0.0);
       },
       {"a"}},
      {"harding-sneddon edge",
       [] {
         (void)harding_sneddon_pressure({2.0, 1.0}, 2.0);
       },
       {"edge"}},
      {"harding-sneddon r < 0",
       [] {
         (void)harding_sneddon_pressure({2.0, 1.0}, -1.0);
       },
       {"radius r"}},
      {"harding-sneddon P < 0",
       [] {
         (void)harding_sneddon_pressure({2.0, -1.0}, 0.0);
       },
       {"load P", "-1"}},
      {"patch p = 0",
       [] {
         (void)patch_test_plane_stress({0.0}, {0.0, 0.0});
       },
       {"pressure p"}},
      {"patch z < 0",
       [] {
         (void)patch_test_plane_stress({1.0}, {0.0, -1.0});
       },
       {"z"}},
      {"patch axi r < 0",
       [] {
         (void)patch_test_axi_stress({1.0}, {-1.0, 0.0});
       },
       {"radius r"}},
  };
}

TEST(BadInput, EveryOracleThrowsInvalidInputWithAOneLineMessage) {
  for (const BadCall& bad : bad_calls()) {
    try {
      bad.call();
      ADD_FAILURE() << bad.label << ": no exception";
    } catch (const InvalidInput& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << bad.label << ": " << what;
      for (const std::string& mention : bad.message_mentions) {
        EXPECT_NE(what.find(mention), std::string::npos)
            << bad.label << ": '" << what << "' does not mention '" << mention << "'";
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << bad.label << ": wrong exception type: " << e.what();
    }
  }
}

TEST(BadInput, InvalidInputIsAnInvalidArgument) {
  EXPECT_THROW((void)hertz_plane_contact({.R = -1.0, .E = 1.0, .nu = 0.3, .P = 1.0}),
               std::invalid_argument);
}

TEST(BadInput, ValuesAreFormattedShortestAndExact) {
  EXPECT_EQ(format_value(0.25), "0.25");
  EXPECT_EQ(format_value(-1.0), "-1");
  EXPECT_EQ(format_value(0.1), "0.1");
  EXPECT_EQ(format_value(1e-300), "1e-300");
  EXPECT_EQ(format_value(kNan), "nan");
  EXPECT_EQ(format_value(-kInf), "-inf");
}

}  // namespace
}  // namespace cs::oracles
