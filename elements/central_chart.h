#ifndef RODNET_ELEMENTS_CENTRAL_CHART_H
#define RODNET_ELEMENTS_CENTRAL_CHART_H

#include <Eigen/Dense>
#include <array>

namespace rodnet
{
  /**
   * The central (gnomonic) chart of the unit sphere S^{d-1} about the
   * direction p = v / |v| of a raw vector v of R^d: the d - 1 coordinates y
   * name the unit vector (p + B y) / |p + B y|, where the columns b_k of B
   * are an orthonormal basis of the plane orthogonal to p.
   *
   * A function of the direction of v alone (a unit tangent e / |e|, a unit
   * quaternion q / |q|) is then a function of d - 1 variables, so a
   * second-order forward derivative carries d^2 numbers per operation
   * instead of (d + 1)^2, and the chain rule back to v is in closed form:
   * y_k(v) = b_k . v / p . v, which at v itself gives
   * - dy_k / dv = b_k / |v|,
   * - d^2 y_k / dv^2 = -(b_k p^T + p b_k^T) / |v|^2,
   * since b_k . v = 0 and p . v = |v| there.
   */
  template <int d>
  class CentralChart
  {
  public:
    using Vector = Eigen::Matrix<double, d, 1>;
    using Basis  = Eigen::Matrix<double, d, d - 1>;

    /// The chart about the direction of @p v (finite, nonzero).
    explicit CentralChart(const Vector &v)
        : inverse_norm(1.0 / v.norm())
        , direction(v * inverse_norm)
    {
      // The Householder reflection taking e_1 to +-p keeps p as its first
      // column; the others complete it orthonormally.
      const Eigen::HouseholderQR<Vector> qr(direction);
      const Eigen::Matrix<double, d, d>  q = qr.householderQ();
      basis                                = q.template rightCols<d - 1>();
    }

    /// The unit vector of coordinates @p y, over any scalar type.
    template <typename Number>
    std::array<Number, d>
    unit(const Number *y) const
    {
      using std::sqrt;
      std::array<Number, d> u;
      Number                norm_squared = 0.0;
      for (int i = 0; i < d; ++i)
        {
          u[i] = direction[i];
          for (int k = 0; k < d - 1; ++k)
            u[i] += basis(i, k) * y[k];
          norm_squared += u[i] * u[i];
        }
      const Number inverse = 1.0 / sqrt(norm_squared);
      for (int i = 0; i < d; ++i)
        u[i] *= inverse;
      return u;
    }

    /// dy / dv at v, (d - 1) x d.
    Eigen::Matrix<double, d - 1, d>
    jacobian() const
    {
      return inverse_norm * basis.transpose();
    }

    /// sum_k w_k d^2 y_k / dv^2 at v, for the weights @p w.
    Eigen::Matrix<double, d, d>
    weighted_second_derivative(const Eigen::Matrix<double, d - 1, 1> &w) const
    {
      const Vector bw = basis * w;
      return -(inverse_norm * inverse_norm) *
             (bw * direction.transpose() + direction * bw.transpose());
    }

  private:
    double inverse_norm;
    Vector direction;
    Basis  basis;
  };
} // namespace rodnet

#endif
