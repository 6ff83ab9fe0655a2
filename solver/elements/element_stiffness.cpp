#include "solver/elements/element_stiffness.hpp"

#include <array>
#include <vector>

#include "solver/elements/gauss_rule.hpp"

namespace cs::solver {
namespace {

/// Shape functions and natural derivatives of one element type at the points of one n x n
/// Gauss rule, computed once.
struct ShapeTable {
  int n_points = 0;
  std::vector<double> weight;                                      // per point
  std::vector<std::array<double, kMaxElementNodes>> N, dxi, deta;  // per point, per node
};

const ShapeTable& shape_table(ElementType type, int gauss_points) {
  static const auto tables = [] {
    std::array<std::array<ShapeTable, kMaxGaussPoints>, 2> all;
    for (int t = 0; t < 2; ++t) {
      const ElementType type = t == 0 ? ElementType::Q4 : ElementType::Q8;
      for (int n = 1; n <= kMaxGaussPoints; ++n) {
        const GaussRule2D& rule = gauss_rule_2d(n);
        ShapeTable& table = all[t][n - 1];
        table.n_points = rule.size();
        for (int q = 0; q < rule.size(); ++q) {
          const ShapeValues s = shape_functions(type, rule.points[q]);
          table.weight.push_back(rule.weights[q]);
          std::array<double, kMaxElementNodes> N{}, dxi{}, deta{};
          for (int a = 0; a < s.n; ++a) {
            N[a] = s.N(a);
            dxi[a] = s.dN_dxi(a, 0);
            deta[a] = s.dN_dxi(a, 1);
          }
          table.N.push_back(N);
          table.dxi.push_back(dxi);
          table.deta.push_back(deta);
        }
      }
    }
    return all;
  }();
  return tables[type == ElementType::Q4 ? 0 : 1][gauss_points - 1];
}

/// K_e for NN nodes, exploiting the sparsity of B: the 2x2 block of nodes (a, b) is
/// B_a^T (D B_b), with B_a = [dx_a 0; 0 dz_a; dz_a dx_a; N_a/r 0] (last row axisymmetric only).
/// Only blocks b <= a are computed; the upper triangle is mirrored.
template <int NN>
void stiffness_kernel(const ElementGeometry& g, const Eigen::Matrix4d& D, int gauss_points,
                      ElementMatrix& K_e) {
  const ShapeTable& table = shape_table(g.type, gauss_points);
  const bool axi = g.analysis == AnalysisType::Axisymmetric;
  double K[2 * NN][2 * NN] = {};
  for (int q = 0; q < table.n_points; ++q) {
    const auto& N = table.N[q];
    const auto& dxi = table.dxi[q];
    const auto& deta = table.deta[q];
    double j00 = 0, j01 = 0, j10 = 0, j11 = 0, r = 0;
    for (int a = 0; a < NN; ++a) {
      j00 += dxi[a] * g.x[a].x();
      j01 += deta[a] * g.x[a].x();
      j10 += dxi[a] * g.x[a].y();
      j11 += deta[a] * g.x[a].y();
      r += N[a] * g.x[a].x();
    }
    const double det = j00 * j11 - j01 * j10;
    if (!(det > 0.0) || (axi && !(r > 0.0))) {
      // Let point_kinematics produce the message naming the element and body.
      point_kinematics(g, gauss_rule_2d(gauss_points).points[q]);
    }
    const double w = table.weight[q] * det * (axi ? r : 1.0);
    const double inv = 1.0 / det;
    double dx[NN], dz[NN], nr[NN];
    for (int a = 0; a < NN; ++a) {
      // [dN/dx dN/dz] = [dN/dxi dN/deta] J^{-1}
      dx[a] = (dxi[a] * j11 - deta[a] * j10) * inv;
      dz[a] = (-dxi[a] * j01 + deta[a] * j00) * inv;
      nr[a] = axi ? N[a] / r : 0.0;
    }
    for (int b = 0; b < NN; ++b) {
      // D B_b (4 x 2), times the weight
      double c0[4], c1[4];
      for (int i = 0; i < 4; ++i) {
        c0[i] = w * (D(i, 0) * dx[b] + D(i, 2) * dz[b] + D(i, 3) * nr[b]);
        c1[i] = w * (D(i, 1) * dz[b] + D(i, 2) * dx[b]);
      }
      for (int a = b; a < NN; ++a) {
        K[2 * a][2 * b] += dx[a] * c0[0] + dz[a] * c0[2] + nr[a] * c0[3];
        K[2 * a][2 * b + 1] += dx[a] * c1[0] + dz[a] * c1[2] + nr[a] * c1[3];
        K[2 * a + 1][2 * b] += dz[a] * c0[1] + dx[a] * c0[2];
        K[2 * a + 1][2 * b + 1] += dz[a] * c1[1] + dx[a] * c1[2];
      }
    }
  }
  K_e.resize(2 * NN, 2 * NN);
  for (int j = 0; j < 2 * NN; ++j) {
    for (int i = j; i < 2 * NN; ++i) {
      K_e(i, j) = K[i][j];  // i >= j: row node >= column node, computed above
      K_e(j, i) = K[i][j];
    }
  }
}

}  // namespace

void element_stiffness(const ElementGeometry& g, const Eigen::Matrix4d& D, int gauss_points,
                       ElementMatrix& K_e) {
  if (g.n_nodes == 4) {
    stiffness_kernel<4>(g, D, gauss_points, K_e);
  } else {
    stiffness_kernel<8>(g, D, gauss_points, K_e);
  }
}

void element_body_force(const ElementGeometry& g, const VectorField& b, int gauss_points,
                        ElementVector& f_e) {
  const GaussRule2D& rule = gauss_rule_2d(gauss_points);
  f_e.setZero(2 * g.n_nodes);
  for (int q = 0; q < rule.size(); ++q) {
    const PointKinematics k = point_kinematics(g, rule.points[q]);
    const Eigen::Vector2d force = b(k.position) * (rule.weights[q] * k.measure());
    for (int a = 0; a < g.n_nodes; ++a) {
      f_e(2 * a) += k.shape.N(a) * force.x();
      f_e(2 * a + 1) += k.shape.N(a) * force.y();
    }
  }
}

Eigen::Vector4d element_stress_at(const ElementGeometry& g, const Eigen::Matrix4d& D,
                                  const ElementVector& u_e, const Eigen::Vector2d& xi) {
  const PointKinematics k = point_kinematics(g, xi);
  const Eigen::Vector4d strain = k.B * u_e;
  return D * strain;
}

}  // namespace cs::solver
