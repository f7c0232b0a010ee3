// The central chart of elements/central_chart.h: the chain rule through it
// must give the very derivatives of a function of a direction that forward
// automatic differentiation in the raw vector gives.
//
// phi(u) = a . u + (b . u)(c . u) + (a . u)^3 of the unit vector
// u = v / |v| is differentiated twice (a) in the raw v, by Sacado over d
// variables, the reference, and (b) in the d - 1 chart coordinates y, then
// carried back by dy/dv and d^2 y / dv^2. Both are exact up to round-off,
// so they must agree to 1e-12 relative to the largest entry, for
// directions spread over the sphere, those next to +-e_1 (where the
// Householder reflection that builds the basis changes sign) and norms
// |v| from 1e-2 to 1e2.

#include <elements/central_chart.h>
#include <elements/frame_algebra.h>

#include "common/relative_error.h"
#include <algorithm>
#include <gtest/gtest.h>
#include <iostream>
#include <random>
#include <vector>

namespace
{
  using namespace rodnet;

  constexpr double chart_tolerance = 1e-12;

  /// The test function of a unit vector, over any scalar type.
  template <int d, typename Number>
  Number
  direction_function(const std::array<Number, d>          &u,
                     const std::array<Eigen::VectorXd, 3> &coefficients)
  {
    Number au = 0.0, bu = 0.0, cu = 0.0;
    for (int i = 0; i < d; ++i)
      {
        au += coefficients[0][i] * u[i];
        bu += coefficients[1][i] * u[i];
        cu += coefficients[2][i] * u[i];
      }
    return au + bu * cu + au * au * au;
  }

  /// The raw vectors to test: random ones, and +-e_1 with a small tilt.
  template <int d>
  std::vector<Eigen::Matrix<double, d, 1>>
  test_vectors(std::mt19937 &rng)
  {
    using Vector = Eigen::Matrix<double, d, 1>;
    std::normal_distribution<double>       normal;
    std::uniform_real_distribution<double> log_norm(-2, 2);
    std::vector<Vector>                    vectors;
    for (unsigned int n = 0; n < 40; ++n)
      {
        Vector v;
        for (int i = 0; i < d; ++i)
          v[i] = normal(rng);
        vectors.push_back(std::pow(10.0, log_norm(rng)) * v.normalized());
      }
    for (const double sign : {1.0, -1.0})
      for (const double tilt : {0.0, 1e-9})
        {
          Vector v = Vector::Zero();
          v[0]     = sign * 3.0;
          v[d - 1] = tilt;
          vectors.push_back(v);
        }
    return vectors;
  }

  template <int d>
  double
  largest_chart_error()
  {
    using Vector = Eigen::Matrix<double, d, 1>;
    std::mt19937                     rng(17);
    std::normal_distribution<double> normal;
    double                           largest = 0;
    for (const Vector &v : test_vectors<d>(rng))
      {
        std::array<Eigen::VectorXd, 3> coefficients;
        for (Eigen::VectorXd &c : coefficients)
          {
            c.resize(d);
            for (int i = 0; i < d; ++i)
              c[i] = normal(rng);
          }

        // (a) In the raw vector.
        Eigen::Matrix<double, 1, 1>                value;
        Eigen::Matrix<double, 1, d>                raw_gradient;
        std::array<Eigen::Matrix<double, d, d>, 1> raw_hessian;
        frame_algebra::differentiate<1, d>(
          v,
          [&](const auto &x) {
            using Number        = std::decay_t<decltype(x[0])>;
            Number norm_squared = 0.0;
            for (int i = 0; i < d; ++i)
              norm_squared += x[i] * x[i];
            using std::sqrt;
            const Number          inverse = 1.0 / sqrt(norm_squared);
            std::array<Number, d> u;
            for (int i = 0; i < d; ++i)
              u[i] = x[i] * inverse;
            return std::array<Number, 1>{
              {direction_function<d>(u, coefficients)}};
          },
          value,
          raw_gradient,
          &raw_hessian);

        // (b) In the chart, carried back.
        const CentralChart<d>                              chart(v);
        Eigen::Matrix<double, 1, d - 1>                    chart_gradient;
        std::array<Eigen::Matrix<double, d - 1, d - 1>, 1> chart_hessian;
        Eigen::Matrix<double, 1, 1>                        chart_value;
        frame_algebra::differentiate<1, d - 1>(
          Eigen::Matrix<double, d - 1, 1>::Zero(),
          [&](const auto &y) {
            return std::array<std::decay_t<decltype(y[0])>, 1>{
              {direction_function<d>(chart.unit(y.data()), coefficients)}};
          },
          chart_value,
          chart_gradient,
          &chart_hessian);
        const Eigen::Matrix<double, d - 1, d> jacobian = chart.jacobian();
        const Eigen::Matrix<double, 1, d> gradient = chart_gradient * jacobian;
        const Eigen::Matrix<double, d, d> hessian =
          jacobian.transpose() * chart_hessian[0] * jacobian +
          chart.weighted_second_derivative(chart_gradient.transpose());

        largest =
          std::max({largest,
                    std::abs(chart_value[0] - value[0]) /
                      std::max(1.0, std::abs(value[0])),
                    rodnet::testing::relative_error(gradient, raw_gradient),
                    rodnet::testing::relative_error(hessian, raw_hessian[0])});
      }
    return largest;
  }

  TEST(CentralChart, ChainRuleEqualsRawDerivatives)
  {
    const double error_3 = largest_chart_error<3>();
    const double error_4 = largest_chart_error<4>();
    std::cout << "central chart against raw AD: largest relative error "
              << error_3 << " on S^2, " << error_4 << " on S^3" << std::endl;
    EXPECT_LT(error_3, chart_tolerance);
    EXPECT_LT(error_4, chart_tolerance);
  }

  TEST(CentralChart, OriginIsTheDirection)
  {
    const Eigen::Vector4d       v(-0.3, 2.0, 0.7, -1.1);
    const CentralChart<4>       chart(v);
    const std::array<double, 3> origin   = {{0, 0, 0}};
    const std::array<double, 4> u        = chart.unit(origin.data());
    const Eigen::Vector4d       expected = v.normalized();
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(u[i], expected[i], 1e-15);
  }
} // namespace
