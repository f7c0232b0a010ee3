#include <elements/dr_beam_kernel.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace
  {
    // Blocks of the two ends, so that the loops over the ends index nothing
    // by arithmetic.
    constexpr std::array<unsigned int, 2> node_block = {
      {dr_dof::node_a, dr_dof::node_b}};
    constexpr std::array<unsigned int, 2> far_block = {
      {dr_dof::far_a, dr_dof::far_b}};
    constexpr std::array<char, 2> end_name = {{'a', 'b'}};

    /// Sine of the angle below which two unit vectors count as parallel in
    /// dr_beam_reference().
    constexpr double parallel_tolerance = 1e-8;

    /// Eqs. 12-13: the normal and its derivatives in one pass.
    void
    normal_with_jacobian(const double                 n_x,
                         const double                 n_y,
                         Vector3                     &normal,
                         Eigen::Matrix<double, 3, 2> &jacobian)
    {
      const double in_plane = n_x * n_x + n_y * n_y;
      if (in_plane <= 1.0)
        {
          const double n_z = std::sqrt(1.0 - in_plane);
          normal << n_x, n_y, n_z;
          jacobian << 1, 0, 0, 1, -n_x / n_z, -n_y / n_z;
        }
      else
        {
          // The normal is (n_x, n_y) / rho in the horizontal plane; its
          // derivative is the projection (I - n n^T) / rho there.
          const double inverse_rho = 1.0 / std::sqrt(in_plane);
          const double x           = n_x * inverse_rho;
          const double y           = n_y * inverse_rho;
          normal << x, y, 0;
          jacobian << (1 - x * x) * inverse_rho, -x * y * inverse_rho,
            -x * y * inverse_rho, (1 - y * y) * inverse_rho, 0, 0;
        }
    }

    [[noreturn]] void
    refuse(const std::string &what)
    {
      throw std::invalid_argument("dr_beam_reference: " + what);
    }

    bool
    parallel(const Vector3 &unit_a, const Vector3 &unit_b)
    {
      return !(unit_a.cross(unit_b).norm() > parallel_tolerance);
    }
  } // namespace


  Vector3
  dr_normal(const double n_x, const double n_y)
  {
    Vector3                     normal;
    Eigen::Matrix<double, 3, 2> jacobian;
    normal_with_jacobian(n_x, n_y, normal, jacobian);
    return normal;
  }


  Eigen::Matrix<double, 3, 2>
  dr_normal_jacobian(const double n_x, const double n_y)
  {
    Vector3                     normal;
    Eigen::Matrix<double, 3, 2> jacobian;
    normal_with_jacobian(n_x, n_y, normal, jacobian);
    return jacobian;
  }


  DrBeamReference
  dr_beam_reference(const DrElementVector &rest_dofs)
  {
    if (!rest_dofs.allFinite())
      refuse("non-finite rest degrees of freedom");

    const Vector3 chord = rest_dofs.segment<3>(dr_dof::node_b) -
                          rest_dofs.segment<3>(dr_dof::node_a);
    if (!(chord.norm() > 0))
      refuse("the element has zero length (X_a = X_b)");
    const Vector3 t1 = chord.normalized();

    DrBeamReference reference;
    for (unsigned int j = 0; j < 2; ++j)
      {
        const unsigned int node = node_block[j];
        const std::string  name = std::string("node ") + end_name[j];
        const Vector3      n    = dr_normal(rest_dofs[node + dr_dof::normal_x],
                                    rest_dofs[node + dr_dof::normal_y]);
        if (parallel(n, t1))
          refuse("the normal of " + name + " is parallel to the chord");

        const Vector3 to_far = rest_dofs.segment<3>(far_block[j]) -
                               rest_dofs.segment<3>(node + dr_dof::position);
        if (!(to_far.norm() > 0))
          refuse("the reference element of " + name + " has zero length");
        const Vector3 r = to_far.normalized();
        if (parallel(n, r))
          refuse("the reference direction of " + name +
                 " is parallel to its normal");

        // The angle about n from f1hat to the projection of t1, whose
        // components along (f1hat, n x f1hat) are those of t1 itself.
        const Vector3 g = (r - r.dot(n) * n).normalized();
        const Vector3 h = n.cross(g);
        reference.alpha[j] =
          std::atan2(t1.dot(h), t1.dot(g)) - rest_dofs[node + dr_dof::rotation];
      }

    const Vector3 normal_sum =
      dr_normal(rest_dofs[dr_dof::node_a + dr_dof::normal_x],
                rest_dofs[dr_dof::node_a + dr_dof::normal_y]) +
      dr_normal(rest_dofs[dr_dof::node_b + dr_dof::normal_x],
                rest_dofs[dr_dof::node_b + dr_dof::normal_y]);
    if (!(normal_sum.norm() > parallel_tolerance))
      refuse("the normals of node a and node b are opposite");
    if (parallel(normal_sum.normalized(), t1))
      refuse("the mean normal of the ends is parallel to the chord, so t2 "
             "(eq. 5) is undefined");

    reference.rest_length = chord.norm();
    const DrBeamKinematics rest_state(rest_dofs, reference);
    const DrBeamStrains   &rest = rest_state.strains();
    reference.rest_twist        = rest.twist;
    reference.rest_tilt         = rest.tilt;
    reference.rest_turn         = rest.turn;
    return reference;
  }


  DrBeamKinematics::DrBeamKinematics(const DrElementVector &dofs,
                                     const DrBeamReference &ref)
  {
    // Eqs. 1, 2, 4.
    const Vector3 chord =
      dofs.segment<3>(dr_dof::node_b) - dofs.segment<3>(dr_dof::node_a);
    const double length = chord.norm();
    inverse_length      = 1.0 / length;
    t1                  = chord * inverse_length;

    for (unsigned int j = 0; j < 2; ++j)
      normal_with_jacobian(dofs[node_block[j] + dr_dof::normal_x],
                           dofs[node_block[j] + dr_dof::normal_y],
                           normal[j],
                           normal_jacobian[j]);

    // Eqs. 3 and 5; t3 (eq. 6) enters no strain.
    const Vector3 normal_sum = normal[0] + normal[1];
    inverse_normal_sum_norm  = 1.0 / normal_sum.norm();
    mean_normal              = normal_sum * inverse_normal_sum_norm;
    const Vector3 w          = mean_normal.cross(t1);
    inverse_t2_norm          = 1.0 / w.norm();
    t2                       = w * inverse_t2_norm;

    current.stretch = length - ref.rest_length;
    current.twist   = t2.dot(normal[1]) - t2.dot(normal[0]) - ref.rest_twist;

    for (unsigned int j = 0; j < 2; ++j)
      {
        const Vector3 &n = normal[j];
        EndFrame      &e = end[j];
        current.tilt[j]  = t1.dot(n) - ref.rest_tilt[j];

        // Eq. 32 with r in place of the reference element's t1: f1 is r
        // projected onto the node's plane.
        const Vector3 to_far =
          dofs.segment<3>(far_block[j]) - dofs.segment<3>(node_block[j]);
        e.inverse_reference_length = 1.0 / to_far.norm();
        e.r                        = to_far * e.inverse_reference_length;
        e.r_dot_n                  = e.r.dot(n);
        const Vector3 f1           = e.r - e.r_dot_n * n;
        e.inverse_f1_norm          = 1.0 / f1.norm();
        e.g                        = f1 * e.inverse_f1_norm;
        e.h                        = n.cross(e.g);

        // Eqs. 34-39: f2 = cos(phi) g + sin(phi) h and f3 = t1 x f2, so
        // theta_3 = f3 . n = t1 . (f2 x n) = t1 . (sin(phi) g - cos(phi) h)
        // since g x n = -h and h x n = g.
        const double angle =
          dofs[node_block[j] + dr_dof::rotation] + ref.alpha[j];
        e.cosine = std::cos(angle);
        e.sine   = std::sin(angle);
        current.turn[j] =
          e.sine * t1.dot(e.g) - e.cosine * t1.dot(e.h) - ref.rest_turn[j];
      }
  }


  void
  DrBeamKinematics::pull_back(const DrBeamStress &stress,
                              DrElementVector    &gradient) const
  {
    // Adjoints (derivatives of sum_s stress_s strain_s) of the forward
    // quantities, in the reverse order of the constructor. The tilts
    // n_j . t1 (eqs. 24-25) seed those of t1 and n_j.
    Vector3 t1_bar = stress.tilt[0] * normal[0] + stress.tilt[1] * normal[1];
    std::array<Vector3, 2> normal_bar = {
      {stress.tilt[0] * t1 - stress.twist * t2,
       stress.tilt[1] * t1 + stress.twist * t2}};

    // Twist t2 . (n_b - n_a) (eq. 18) through t2 = w / |w| with
    // w = n^k x t1 (eq. 5) and n^k = m / |m| with m = n_a + n_b (eq. 3).
    const Vector3 t2_bar = stress.twist * (normal[1] - normal[0]);
    const Vector3 w_bar  = (t2_bar - t2.dot(t2_bar) * t2) * inverse_t2_norm;
    t1_bar += w_bar.cross(mean_normal);
    const Vector3 mean_normal_bar = t1.cross(w_bar);
    const Vector3 normal_sum_bar =
      (mean_normal_bar - mean_normal.dot(mean_normal_bar) * mean_normal) *
      inverse_normal_sum_norm;

    // Every entry of the gradient is assigned in the loop before the chord
    // adds to the positions.
    for (unsigned int j = 0; j < 2; ++j)
      {
        const EndFrame &e = end[j];
        const Vector3  &n = normal[j];
        const double    s = stress.turn[j];
        normal_bar[j] += normal_sum_bar;

        // theta_3 = sin(phi) t1 . g - cos(phi) t1 . h (see the constructor);
        // eqs. 34-36 for phi = n_r + alpha.
        t1_bar += s * (e.sine * e.g - e.cosine * e.h);
        gradient[node_block[j] + dr_dof::rotation] =
          s * (e.cosine * t1.dot(e.g) + e.sine * t1.dot(e.h));

        // h = n x g.
        const Vector3 h_bar = -s * e.cosine * t1;
        normal_bar[j] += e.g.cross(h_bar);
        const Vector3 g_bar = s * e.sine * t1 + h_bar.cross(n);

        // g = f1 / |f1| (eq. 33), f1 = r - (r . n) n (eq. 32), r = d / |d|
        // with d = X_{c_j} - X_j.
        const Vector3 f1_bar =
          (g_bar - e.g.dot(g_bar) * e.g) * e.inverse_f1_norm;
        const double n_dot_f1_bar = n.dot(f1_bar);
        normal_bar[j] -= n_dot_f1_bar * e.r + e.r_dot_n * f1_bar;
        const Vector3 r_bar = f1_bar - n_dot_f1_bar * n;
        const Vector3 d_bar =
          (r_bar - e.r.dot(r_bar) * e.r) * e.inverse_reference_length;
        gradient.segment<3>(far_block[j])                     = d_bar;
        gradient.segment<3>(node_block[j] + dr_dof::position) = -d_bar;

        // Eqs. 12-13.
        gradient.segment<2>(node_block[j] + dr_dof::normal_x) =
          normal_jacobian[j].transpose() * normal_bar[j];
      }

    // t1 = v / L (eq. 14) and dL/dv = t1 (eq. 16).
    const Vector3 v_bar =
      (t1_bar - t1.dot(t1_bar) * t1) * inverse_length + stress.stretch * t1;
    gradient.segment<3>(dr_dof::node_a) -= v_bar;
    gradient.segment<3>(dr_dof::node_b) += v_bar;
  }
} // namespace rodnet
