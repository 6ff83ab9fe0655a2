// Bad input to the FE core: a ModelError (a std::invalid_argument) with a one-line message that
// names the cause (element and body, set, body, node), never a crash or a NaN.

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "solver/linear_static.hpp"
#include "solver/model_error.hpp"
#include "test_fe_support.hpp"

namespace cs::solver {
namespace {

Model valid_model(ElementType type = ElementType::Q4) {
  Model model;
  model.mesh = test::block(type, {0, 0}, {2, 1}, 4, 2, "block");
  model.materials = {{100.0, 0.3}};
  model.fix(NodeSelection::node_set("bottom"), Component::Z);
  model.fix(NodeSelection::node_set("left"), Component::X);
  model.loads.add_pressure("top", 1.0);
  return model;
}

/// Expects solve_linear_static(model) to throw a ModelError whose one-line message contains
/// every one of `parts`.
void expect_model_error(const Model& model, std::initializer_list<std::string> parts) {
  try {
    solve_linear_static(model);
    ADD_FAILURE() << "no ModelError";
  } catch (const ModelError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    for (const std::string& part : parts) {
      EXPECT_NE(what.find(part), std::string::npos) << "'" << part << "' not in: " << what;
    }
  }
}

TEST(FeBadInput, ValidModelSolves) {
  EXPECT_TRUE(solve_linear_static(valid_model()).ok());
}

// Requirement: an inverted (clockwise) element is named with its body.
TEST(FeBadInput, InvertedElementIsNamed) {
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    Model model = valid_model(type);
    auto& e = model.mesh.elements[5];
    std::swap(e[1], e[3]);  // reverses the corner order
    if (type == ElementType::Q8) {
      std::swap(e[4], e[7]);
      std::swap(e[5], e[6]);
    }
    expect_model_error(model, {"element 5 of body 'block'", "det J"});
  }
}

// Requirement: a degenerate element (zero area: det J = 0 at its Gauss points) is named with
// its body. (A quadrilateral collapsed to a triangle keeps det J > 0 at its Gauss points and
// is accepted, as commercial codes accept it.)
TEST(FeBadInput, DegenerateElementIsNamed) {
  Model model = valid_model();
  model.mesh = test::block(ElementType::Q4, {0, 0}, {1, 1}, 1, 1, "sliver");
  for (int n : model.mesh.node_sets.at("top"))
    model.mesh.nodes[n].y() = 0.0;
  expect_model_error(model, {"element 0 of body 'sliver'", "det J"});
}

// Requirement: nu outside [0, 0.5) or E <= 0 is rejected, naming the body.
TEST(FeBadInput, BadMaterialIsNamed) {
  for (const Material bad : {Material{100.0, 0.5}, Material{100.0, -0.2}, Material{0.0, 0.3},
                             Material{-5.0, 0.3}, Material{std::nan(""), 0.3}}) {
    Model model = valid_model();
    model.materials[0] = bad;
    expect_model_error(model, {"body 'block'"});
  }
  Model missing = valid_model();
  missing.materials.clear();
  expect_model_error(missing, {"0 materials given for 1 bodies"});
}

// Requirement: unknown or empty node and edge sets are named.
TEST(FeBadInput, UnknownOrEmptySetIsNamed) {
  Model unknown_node_set = valid_model();
  unknown_node_set.fix(NodeSelection::node_set("nowhere"), Component::Z);
  expect_model_error(unknown_node_set, {"unknown node set 'nowhere'"});

  Model empty = valid_model();
  empty.mesh.node_sets["hollow"] = {};
  empty.fix(NodeSelection::node_set("hollow"), Component::X);
  expect_model_error(empty, {"node set 'hollow' is empty"});

  Model unknown_edge_set = valid_model();
  unknown_edge_set.loads.add_traction("rim", constant_field(Eigen::Vector2d(1, 0)));
  expect_model_error(unknown_edge_set, {"unknown edge set 'rim'"});

  Model empty_edge_set = valid_model();
  empty_edge_set.mesh.edge_sets["rim"] = {};
  empty_edge_set.loads.add_pressure("rim", 1.0);
  expect_model_error(empty_edge_set, {"edge set 'rim' is empty"});

  Model bad_node = valid_model();
  bad_node.loads.add_point_force(NodeSelection::list({0, 999}, "tip"), {1.0, 0.0});
  expect_model_error(bad_node, {"node list 'tip'", "999"});
}

// Requirement: a DOF prescribed twice with different values is a conflict, named.
TEST(FeBadInput, ConflictingPrescribedValues) {
  Model model = valid_model();
  model.fix(NodeSelection::node_set("left"), Component::Z, 0.1);  // bottom-left corner: 0 and 0.1
  expect_model_error(model, {"prescribed twice", "node 0"});
}

// Requirement: non-finite prescribed values and forces are rejected (no NaN reaches a result).
TEST(FeBadInput, NonFiniteValues) {
  Model nan_value = valid_model();
  nan_value.prescribe(NodeSelection::node_set("right"), Component::X,
                      [](const Eigen::Vector2d&) { return std::nan(""); });
  expect_model_error(nan_value, {"node set 'right'", "not finite"});

  Model nan_force = valid_model();
  nan_force.loads.add_point_force(NodeSelection::node_set("top"),
                                  {std::numeric_limits<double>::infinity(), 0.0});
  expect_model_error(nan_force, {"point force on node set 'top' is not finite"});
}

// Requirement: an axisymmetric mesh must lie in r >= 0; other structural errors are named.
TEST(FeBadInput, AxisymmetricMeshCrossingTheAxis) {
  Model model = valid_model();
  model.analysis = AnalysisType::Axisymmetric;
  for (auto& x : model.mesh.nodes)
    x.x() -= 0.5;
  expect_model_error(model, {"axisymmetric", "r >= 0"});

  Model bad_body = valid_model();
  bad_body.mesh.element_body[3] = 4;
  expect_model_error(bad_body, {"element 3", "body index 4"});

  Model bad_force = valid_model();
  bad_force.loads.add_body_force(constant_field(Eigen::Vector2d(0, -1)), 2);
  expect_model_error(bad_force, {"body index 2"});

  Model bad_points = valid_model();
  bad_points.quadrature.edge_points = 40;
  expect_model_error(bad_points, {"quadrature.edge_points", "40"});
}

// Requirement: ModelError is a std::invalid_argument (the app turns it into exit code 2).
TEST(FeBadInput, ModelErrorIsInvalidArgument) {
  Model model = valid_model();
  model.materials[0].poissons_ratio_nu = 0.5;
  EXPECT_THROW(solve_linear_static(model), std::invalid_argument);
}

}  // namespace
}  // namespace cs::solver
