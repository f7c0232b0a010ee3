// Mass matrix of a rod network for implicit dynamics (Lestringant &
// Kochmann section 2.5, following Lestringant, Audoly & Kochmann 2020):
// translational inertia of the vertex positions, consistent or lumped, the
// rotary inertia of the sections about their bending axes, and the
// rotational inertia of each segment's twist about its tangent.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <core/mass_matrix.h>
#include <core/require_positive.h>
#include <core/rigid_body_mass.h>

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
    check_inertia(const SolvableModel           &model,
                  const std::vector<RodInertia> &inertia)
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
          require_inertia(inertia[r].rotary_inertia_per_length,
                          "rotary inertia per length (kg m)",
                          r);
        }
    }

    /**
     * The inertia of one segment (the cell of @p fe_values) in @p cell_mass:
     * rho A N_i N_j on the positions by the quadrature of @p fe_values,
     * rho (I1 + I2) on the twist, and the rotary inertia
     * rho I_b N_i' N_j' on the positions, the kinetic energy
     * rho I_b l0 / 2 |(xdot_{j+1} - xdot_j) / l0|^2 of the sections turning
     * with the chord (doc/theory.md, "Rotary inertia"). N' is constant on a
     * segment, so any rule with weights summing to l0 integrates it exactly.
     */
    void
    segment_mass(const dealii::FEValues<1, 3> &fe_values,
                 const RodInertia             &rod,
                 dealii::FullMatrix<double>   &cell_mass)
    {
      const dealii::FiniteElement<1, 3> &fe = fe_values.get_fe();
      cell_mass                             = 0;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          // Positions carry rho A; the twist carries rho (I1 + I2), the
          // rotation of the cross-sections about the tangent at the
          // twist rate (doc/theory.md).
          const unsigned int component = fe.system_to_component_index(i).first;
          const double       density   = component < 3 ?
                                           rod.mass_per_length :
                                           rod.rotational_inertia_per_length;
          const double       rotary =
            component < 3 ? rod.rotary_inertia_per_length : 0.0;
          for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
            if (fe.system_to_component_index(j).first == component)
              for (const unsigned int q : fe_values.quadrature_point_indices())
                cell_mass(i, j) += (density * fe_values.shape_value(i, q) *
                                      fe_values.shape_value(j, q) +
                                    rotary * fe_values.shape_grad(i, q) *
                                      fe_values.shape_grad(j, q)) *
                                   fe_values.JxW(q);
        }
    }
  } // namespace

  bool
  adds_here(const MatrixType &matrix, const global_dof_index anchor)
  {
    const auto [first, end] = matrix.local_range();
    return anchor >= first && anchor < end;
  }

  RodInertia
  rod_inertia(const CrossSection &section, const double density)
  {
    require_positive(density, "rod inertia: the density");
    return {density * section.area,
            density * (section.I1 + section.I2),
            density * (section.I1 + section.I2) / 2};
  }

  void
  assemble_mass_matrix(const SolvableModel           &model,
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

    // Gauss points integrate N_a N_b of the linear shape functions exactly
    // (rho A l0 / 6 [[2, 1], [1, 2]]); the trapezoidal rule puts each row
    // sum on the diagonal (rho A l0 / 2 at each end): the lumped mass.
    const dealii::FiniteElement<1, 3> &fe = model.layout().segment_fe();
    const dealii::Quadrature<1>        quadrature =
      kind == MassKind::consistent ?
               dealii::Quadrature<1>(dealii::QGauss<1>(2)) :
               dealii::Quadrature<1>(dealii::QTrapezoid<1>());
    dealii::FEValues<1, 3> fe_values(fe,
                                     quadrature,
                                     dealii::update_values |
                                       dealii::update_gradients |
                                       dealii::update_JxW_values);

    // The junction copies condense onto their junction vertices (every
    // segment there adds its mass once); with apply_constraints the fixed
    // DoFs drop out as well.
    const dealii::AffineConstraints<double> &constraints =
      apply_constraints ? model.constraints() :
                          model.layout().junction_constraints();
    model.initialize_matrix(mass);
    dealii::FullMatrix<double>    cell_mass(fe.n_dofs_per_cell(),
                                         fe.n_dofs_per_cell());
    std::vector<global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : model.layout().segment_cells())
      {
        // Each segment once, on several processes too (adds_here()).
        cell->get_dof_indices(dofs);
        if (!adds_here(mass, dofs[0]))
          continue;
        fe_values.reinit(cell);
        segment_mass(fe_values, inertia[cell->material_id()], cell_mass);
        constraints.distribute_local_to_global(cell_mass, dofs, mass);
      }
    add_rigid_body_mass(model, constraints, mass);
    mass.compress(dealii::VectorOperation::add);

    // deal.II keeps constrained rows invertible with a diagonal entry; here
    // they carry no inertia (M is the condensed mass of the free DoFs).
    std::vector<global_dof_index> constrained;
    for (const auto &line : constraints.get_lines())
      constrained.push_back(line.index);
    mass.clear_rows(constrained, 0.0);
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

  void
  copy_nonzeros(const MatrixType &from, MatrixType &to)
  {
    // Row views of the Trilinos matrix: deal.II's iterators copy each row
    // they visit, which costs seconds on 1e5 rows.
    const Epetra_CrsMatrix &m = from.trilinos_matrix();
    std::vector<std::vector<dealii::types::global_dof_index>> columns(
      m.NumMyRows());
    std::vector<std::vector<double>>          values(m.NumMyRows());
    dealii::TrilinosWrappers::SparsityPattern pattern(
      from.locally_owned_range_indices(),
      from.get_mpi_communicator());
    for (int i = 0; i < m.NumMyRows(); ++i)
      {
        int     n     = 0;
        double *row   = nullptr;
        int    *local = nullptr;
        m.ExtractMyRowView(i, n, row, local);
        const auto global =
          static_cast<dealii::types::global_dof_index>(m.GRID64(i));
        // The diagonal of every row keeps every column in the pattern,
        // so that a product imports nothing.
        bool diagonal = false;
        for (int k = 0; k < n; ++k)
          {
            const auto column =
              static_cast<dealii::types::global_dof_index>(m.GCID64(local[k]));
            diagonal = diagonal || column == global;
            if (row[k] != 0 || column == global)
              {
                columns[i].push_back(column);
                values[i].push_back(row[k]);
              }
          }
        if (!diagonal)
          {
            columns[i].push_back(global);
            values[i].push_back(0.0);
          }
        pattern.add_entries(global, columns[i].begin(), columns[i].end());
      }
    pattern.compress();
    to.reinit(pattern);
    for (int i = 0; i < m.NumMyRows(); ++i)
      to.set(static_cast<dealii::types::global_dof_index>(m.GRID64(i)),
             columns[i].size(),
             columns[i].data(),
             values[i].data());
    to.compress(dealii::VectorOperation::insert);
  }
} // namespace rodnet
