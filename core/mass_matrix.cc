// Mass matrix of a rod network for implicit dynamics (Lestringant &
// Kochmann section 2.5, following Lestringant, Audoly & Kochmann 2020):
// translational inertia of the vertex positions, consistent or lumped, and
// the rotational inertia of each segment's twist about its tangent.
#include <core/mass_matrix.h>
#include <core/require_positive.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace
  {
    void
    require_inertia(const double       value,
                    const char        *what,
                    const unsigned int rod)
    {
      if (!(value >= 0) || !std::isfinite(value))
        throw std::invalid_argument(
          "mass matrix: rod " + std::to_string(rod) + " has " + what + " " +
          std::to_string(value) + "; it must be finite and not negative");
    }

    void
    check_inertia(const RodModel &model, const std::vector<RodInertia> &inertia)
    {
      const std::size_t n_rods = model.network().rods().size();
      if (inertia.size() < n_rods)
        throw std::invalid_argument(
          "mass matrix: no inertia for rod " + std::to_string(inertia.size()) +
          " (" + std::to_string(inertia.size()) + " given for " +
          std::to_string(n_rods) + " rods)");
      if (inertia.size() > n_rods)
        throw std::invalid_argument("mass matrix: inertia given for rod " +
                                    std::to_string(n_rods) +
                                    ", which does not exist (the network has " +
                                    std::to_string(n_rods) + " rods)");
      for (unsigned int r = 0; r < n_rods; ++r)
        {
          require_inertia(inertia[r].mass_per_length,
                          "mass per length (kg/m)",
                          r);
          require_inertia(inertia[r].rotational_inertia_per_length,
                          "rotational inertia per length (kg m)",
                          r);
        }
    }
  } // namespace

  RodInertia
  rod_inertia(const CrossSection &section, const double density)
  {
    require_positive(density, "rod inertia: the density");
    return {density * section.area, density * (section.I1 + section.I2)};
  }

  void
  assemble_mass_matrix(const RodModel                &model,
                       const std::vector<RodInertia> &inertia,
                       const MassKind                 kind,
                       MatrixType                    &mass,
                       const bool                     apply_constraints)
  {
    // finalize() builds the sparsity pattern and the constraints together
    // with the load vector, which is empty until then.
    if (model.external_force().size() != model.layout().n_dofs())
      throw std::logic_error(
        "mass matrix: the model must be finalized (RodModel::finalize)");
    check_inertia(model, inertia);

    const DofLayout                         &layout      = model.layout();
    const dealii::AffineConstraints<double> &constraints = model.constraints();
    std::vector<bool>                        fixed(layout.n_dofs(), false);
    if (apply_constraints)
      for (global_dof_index i = 0; i < layout.n_dofs(); ++i)
        if (constraints.is_constrained(i))
          {
            // The model only fixes DoFs; zero rows and columns are then the
            // exact condensation of M onto the free DoFs.
            Assert(constraints.get_constraint_entries(i)->empty(),
                   dealii::ExcMessage("mass matrix: a constraint that ties "
                                      "DoFs together is not supported"));
            fixed[i] = true;
          }

    model.initialize_matrix(mass);
    const auto add = [&](const global_dof_index i,
                         const global_dof_index j,
                         const double           value) {
      if (!fixed[i] && !fixed[j])
        mass.add(i, j, value);
    };

    for (const SegmentStencil &s : layout.segments())
      {
        const double l0 = model.configuration().rest_length(s.cell);
        const double m  = inertia[s.rod].mass_per_length * l0;
        // m int_0^1 N_a N_b with N_0 = 1 - xi, N_1 = xi; lumping moves each
        // row sum onto the diagonal.
        const double diagonal = kind == MassKind::consistent ? m / 3 : m / 2;
        const double coupling = kind == MassKind::consistent ? m / 6 : 0;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const global_dof_index start = s.dofs[c], end = s.dofs[3 + c];
            add(start, start, diagonal);
            add(end, end, diagonal);
            if (kind == MassKind::consistent)
              {
                add(start, end, coupling);
                add(end, start, coupling);
              }
          }
        // Rotation of the cross-sections about the tangent at the twist
        // rate: the twist-angle part of the material frame's angular
        // velocity (doc/theory.md).
        const global_dof_index twist = layout.twist_dof(s.cell);
        add(twist, twist, inertia[s.rod].rotational_inertia_per_length * l0);
      }
    mass.compress(dealii::VectorOperation::add);
  }

  double
  kinetic_energy(const MatrixType &mass, const VectorType &velocity)
  {
    if (velocity.size() != mass.m())
      throw std::invalid_argument(
        "kinetic energy: the velocity has " + std::to_string(velocity.size()) +
        " entries, the mass matrix " + std::to_string(mass.m()) + " rows");
    return 0.5 * mass.matrix_norm_square(velocity);
  }
} // namespace rodnet
