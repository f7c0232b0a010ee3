// The weight of rigid bodies off their vertex (families/body_weight_family.h).
#include <core/rod_model.h>

#include <families/body_weight_family.h>

namespace rodnet
{
  BodyWeightFamily::BodyWeightFamily(const DofLayout        &layout,
                                     std::vector<BodyWeight> weights)
      : layout(layout)
      , weights(std::move(weights))
  {
  }

  void
  BodyWeightFamily::get_dofs(const unsigned int             s,
                             std::vector<global_dof_index> &dofs) const
  {
    dofs.clear();
    for (unsigned int c = 0; c < 4; ++c)
      dofs.push_back(layout.rotation_dof(weights[s].junction, c));
  }

  namespace
  {
    /// A with a . R(q) b |q|^2 = q^T A q for quaternions q = (w, x):
    /// R(q) b |q|^2 = (w^2 - |x|^2) b + 2 (x . b) x + 2 w x x b.
    Eigen::Matrix4d
    lever_form(const Vector3 &a, const Vector3 &b)
    {
      Eigen::Matrix4d A;
      A(0, 0)             = a.dot(b);
      A.block<3, 1>(1, 0) = b.cross(a);
      A.block<1, 3>(0, 1) = b.cross(a).transpose();
      A.block<3, 3>(1, 1) =
        -a.dot(b) * Matrix3::Identity() + a * b.transpose() + b * a.transpose();
      return A;
    }
  } // namespace

  void
  BodyWeightFamily::evaluate(const unsigned int  s,
                             const StencilState &state,
                             const Derivatives   derivatives,
                             LocalContribution  &local) const
  {
    const BodyWeight &w = weights[s];
    // The DoFs store the increment since the reference, q - (1, 0, 0, 0).
    Eigen::Vector4d q;
    for (unsigned int c = 0; c < 4; ++c)
      q[c] = state.u[layout.rotation_dof(w.junction, c)] + (c == 0);
    const Vector3 b =
      state.configuration.reference_rotation(w.junction) * w.offset;
    const Eigen::Matrix4d A     = lever_form(w.weight, b);
    const double          scale = -state.load_factor;
    // phi = N / s, N = q^T A q, s = q^T q.
    const double s2 = q.squaredNorm(), N = q.dot(A * q);
    local.energy = scale * N / s2;
    if (derivatives == Derivatives::energy)
      return;
    const Eigen::Vector4d Aq = A * q;
    const Eigen::Vector4d gradient =
      scale * (2 * Aq / s2 - 2 * N * q / (s2 * s2));
    const Eigen::Matrix4d qq = q * q.transpose();
    const Eigen::Matrix4d hessian =
      scale *
      (2 * A / s2 - 4 * (Aq * q.transpose() + q * Aq.transpose()) / (s2 * s2) -
       2 * N / (s2 * s2) * Eigen::Matrix4d::Identity() +
       8 * N * qq / (s2 * s2 * s2));
    local.store(gradient,
                derivatives == Derivatives::hessian ? &hessian : nullptr);
  }

  std::unique_ptr<ElementFamily>
  body_weight_family(const RodModel &model, const Vector3 &gravity)
  {
    std::vector<BodyWeight> weights;
    for (const RigidBody &body : model.rigid_bodies())
      if (body.has_centre_offset() && gravity != Vector3::Zero())
        {
          // check_rigid_body() put the body on a junction with a rotation.
          const unsigned int v = std::get<unsigned int>(body.attachment);
          weights.push_back({*model.network().junction_at(v),
                             body.mass * gravity,
                             body.centre_offset});
        }
    if (weights.empty())
      return nullptr;
    return std::make_unique<BodyWeightFamily>(model.layout(),
                                              std::move(weights));
  }
} // namespace rodnet
