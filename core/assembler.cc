// Assembly of the total potential energy of a RodModel, its gradient and
// its Hessian: for every stencil, element kernel (strains and their
// derivatives) -> material (energy, stress, tangent) -> chain rule ->
// constraints -> global Trilinos objects.
#include <deal.II/base/work_stream.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <core/rod_model.h>
#include <elements/junction_moment.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <array>
#include <atomic>
#include <exception>
#include <mutex>

namespace rodnet
{
  namespace
  {
    /// What one stencil contributes; filled by a worker thread, added to
    /// the global objects by the (serial) copier.
    struct LocalContribution
    {
      dealii::FullMatrix<double>    matrix;
      dealii::Vector<double>        vector;
      std::vector<global_dof_index> dofs;
      double                        energy = 0;
    };

    struct Scratch
    {
      HingeStrains  hinge;
      StretchStrain stretch;
    };

    /// Copies an Eigen gradient/Hessian pair into the copy data.
    template <int n>
    void
    store(const Eigen::Matrix<double, n, 1> &gradient,
          const Eigen::Matrix<double, n, n> *hessian,
          LocalContribution                 &copy)
    {
      copy.vector.reinit(n);
      for (int i = 0; i < n; ++i)
        copy.vector[i] = gradient[i];
      if (hessian != nullptr)
        {
          copy.matrix.reinit(n, n);
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
              copy.matrix(i, j) = (*hessian)(i, j);
        }
    }
    /**
     * Adds local contributions straight into the compressed rows of the
     * Trilinos matrix and the vector's storage. Valid on one process, where
     * row and column maps are the identity, for constraints that only fix
     * DoFs (rows and columns of fixed DoFs are skipped; their diagonal is
     * set by finish()). It replaces AffineConstraints::
     * distribute_local_to_global, whose per-entry global-to-local lookups
     * and searches cost more than the kernels (see doc/performance.md).
     */
    class DirectScatter
    {
    public:
      /// Whether the fast path applies to @p matrix (or to vectors alone).
      static bool
      applies(const MatrixType *matrix)
      {
        if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 1)
          return false;
        if (matrix == nullptr)
          return true;
        const Epetra_CrsMatrix &m = matrix->trilinos_matrix();
        if (!(m.RowMap().LinearMap() && m.ColMap().LinearMap() &&
              m.ColMap().MinMyGID() == 0 && m.RowMap().MinMyGID() == 0 &&
              m.ColMap().NumMyElements() == m.RowMap().NumMyElements()))
          return false;
        // Epetra sorts the column indices of each row when the matrix is
        // filled; the merge in add() relies on it, so check (as cheap as
        // zeroing the matrix).
        for (int row = 0; row < m.NumMyRows(); ++row)
          {
            int     length;
            double *row_values;
            int    *columns;
            m.ExtractMyRowView(row, length, row_values, columns);
            if (!std::is_sorted(columns, columns + length))
              return false;
          }
        return true;
      }

      DirectScatter(MatrixType              *matrix,
                    VectorType              *vector,
                    const std::vector<bool> *fixed)
          : matrix(matrix == nullptr ?
                     nullptr :
                     &const_cast<Epetra_CrsMatrix &>(matrix->trilinos_matrix()))
          , values(vector == nullptr ? nullptr : vector->trilinos_vector()[0])
          , fixed(fixed)
      {
      }

      void
      add(const LocalContribution &copy) const
      {
        const unsigned int n = copy.dofs.size();
        // The stencil's DoFs in increasing order, so that each row is
        // merged with the sorted column indices of the matrix in one pass.
        std::array<unsigned char, n_hinge_dofs> order;
        for (unsigned int i = 0; i < n; ++i)
          {
            unsigned int k = i;
            for (; k > 0 && copy.dofs[order[k - 1]] > copy.dofs[i]; --k)
              order[k] = order[k - 1];
            order[k] = i;
          }
        for (unsigned int a = 0; a < n; ++a)
          {
            const unsigned int i   = order[a];
            const int          row = copy.dofs[i];
            if (is_fixed(row))
              continue;
            if (values != nullptr)
              values[row] += copy.vector[i];
            if (matrix == nullptr)
              continue;
            int     length;
            double *row_values;
            int    *columns;
            matrix->ExtractMyRowView(row, length, row_values, columns);
            int k = 0;
            for (unsigned int b = 0; b < n; ++b)
              {
                const unsigned int j   = order[b];
                const int          col = copy.dofs[j];
                if (is_fixed(col))
                  continue;
                while (columns[k] < col)
                  ++k;
                row_values[k] += copy.matrix(i, j);
              }
          }
      }

      /// Puts the mean free diagonal on the rows of fixed DoFs, so that
      /// the Newton increment is zero there and the scale matches.
      void
      finish() const
      {
        if (matrix == nullptr || fixed == nullptr)
          return;
        double       sum    = 0;
        unsigned int n_free = 0;
        for (int row = 0; row < matrix->NumMyRows(); ++row)
          if (!(*fixed)[row])
            {
              sum += std::abs(diagonal(row));
              ++n_free;
            }
        const double value = n_free > 0 ? sum / n_free : 1.0;
        for (int row = 0; row < matrix->NumMyRows(); ++row)
          if ((*fixed)[row])
            diagonal(row) = value;
      }

    private:
      bool
      is_fixed(const int dof) const
      {
        return fixed != nullptr && (*fixed)[dof];
      }

      double &
      diagonal(const int row) const
      {
        int     length;
        double *row_values;
        int    *columns;
        matrix->ExtractMyRowView(row, length, row_values, columns);
        return row_values[std::lower_bound(columns, columns + length, row) -
                          columns];
      }

      Epetra_CrsMatrix        *matrix;
      double                  *values;
      const std::vector<bool> *fixed;
    };
  } // namespace

  double
  RodModel::assemble(const VectorType &u,
                     const double      load_factor,
                     VectorType       *residual,
                     MatrixType       *tangent,
                     const bool        apply_constraints,
                     const VectorType *extra_force) const
  {
    const dealii::AffineConstraints<double> &constraints =
      apply_constraints ? homogeneous_constraints : no_constraints;
    if (residual != nullptr)
      *residual = 0;
    if (tangent != nullptr)
      *tangent = 0;
    const bool with_gradient = residual != nullptr || tangent != nullptr;
    const bool with_hessian  = tangent != nullptr;

    double             energy = 0;
    std::exception_ptr failure;
    std::mutex         failure_mutex;

    // Kernels throw, e.g., where a tangent flipped; the first exception is
    // rethrown after the loop so that the caller can cut the step.
    auto guarded = [&](auto &&work) {
      try
        {
          work();
        }
      catch (...)
        {
          std::lock_guard<std::mutex> lock(failure_mutex);
          if (!failure)
            failure = std::current_exception();
        }
    };

    const bool          direct = DirectScatter::applies(tangent);
    const DirectScatter scatter(tangent,
                                residual,
                                apply_constraints ? &fixed_dof_mask : nullptr);
    auto                copier = [&](const LocalContribution &copy) {
      energy += copy.energy;
      if (!with_gradient || copy.dofs.empty())
        return;
      if (direct)
        scatter.add(copy);
      else if (with_hessian && residual != nullptr)
        constraints.distribute_local_to_global(copy.matrix,
                                               copy.vector,
                                               copy.dofs,
                                               *tangent,
                                               *residual);
      else if (with_hessian)
        constraints.distribute_local_to_global(copy.matrix,
                                               copy.dofs,
                                               *tangent);
      else
        constraints.distribute_local_to_global(copy.vector,
                                               copy.dofs,
                                               *residual);
    };

    // Hinges and junction elements share the bending and twisting part:
    // strains -> material -> chain rule.
    // Materials see the strains, the committed internal variables of the
    // stencil and the time step; elastic ones ignore the last two. Nothing
    // is written back here (see commit_internal_variables()).
    auto bending = [&](const HingeStrains &strains,
                       const RodMaterial  &material,
                       const double        voronoi_length,
                       const double       *committed,
                       LocalContribution  &copy) {
      const MaterialResponse<3> w = material.hinge_increment(strains.kappa,
                                                             voronoi_length,
                                                             committed,
                                                             step_length,
                                                             nullptr);
      copy.energy                 = w.energy;
      const HingeVector gradient  = strains.gradient.transpose() * w.stress;
      HingeMatrix       hessian;
      if (with_hessian)
        {
          // Elastic part J^T C J and geometric part sum_k s_k d2kappa_k
          // (Korner et al. eq. 4.5).
          const Eigen::Matrix<double, 3, n_hinge_dofs> cj =
            w.tangent * strains.gradient;
          hessian.noalias() = strains.gradient.transpose() * cj;
          for (unsigned int c = 0; c < 3; ++c)
            hessian += w.stress[c] * strains.hessian[c];
        }
      store<n_hinge_dofs>(gradient, with_hessian ? &hessian : nullptr, copy);
    };

    // Hinges and junction elements differ only in where their kernel,
    // reference, local DoFs, Voronoi length, internal variables and natural
    // strains come from: one pass serves both. @p element(i, stencil)
    // returns those for stencil i. The material sees the strains minus the
    // natural ones (doc/theory.md, "Natural shape"); their derivatives are
    // the kernel's.
    const auto bending_pass = [&](const auto &stencils, const auto &element) {
      dealii::WorkStream::run(
        stencils.begin(),
        stencils.end(),
        [&](const auto &it, Scratch &scratch, LocalContribution &copy) {
          copy.dofs.clear();
          copy.energy = 0;
          guarded([&] {
            const auto [k, ref, x, l, committed, natural] =
              element(it - stencils.begin(), *it);
            if (!with_gradient)
              {
                copy.energy = materials[it->rod]
                                ->hinge_increment(k->strains(x, ref) - natural,
                                                  l,
                                                  committed,
                                                  step_length,
                                                  nullptr)
                                .energy;
                return;
              }
            k->evaluate(x, ref, scratch.hinge, with_hessian);
            scratch.hinge.kappa -= natural;
            bending(scratch.hinge, *materials[it->rod], l, committed, copy);
            copy.dofs.assign(it->dofs.begin(), it->dofs.end());
          });
        },
        copier,
        Scratch(),
        LocalContribution());
    };
    bending_pass(layout_->hinges(),
                 [&](const unsigned int h, const HingeStencil &stencil) {
                   return std::make_tuple(
                     kernels[stencil.rod].get(),
                     std::cref(configuration_->hinge_reference(h)),
                     configuration_->hinge_dofs(u, stencil),
                     configuration_->voronoi_length(h),
                     history.block(InternalVariables::Owner::hinge, h),
                     configuration_->natural_strains(h));
                 });
    bending_pass(layout_->junctions(),
                 [&](const unsigned int e, const JunctionStencil &stencil) {
                   return std::make_tuple(
                     junction_kernels[stencil.rod].get(),
                     std::cref(configuration_->junction_reference(e)),
                     configuration_->junction_dofs(u, stencil),
                     configuration_->junction_voronoi_length(e),
                     history.block(InternalVariables::Owner::junction_element,
                                   e),
                     // Stress free where built: the ghost frame starts as
                     // the segment's (Configuration).
                     Vector3(Vector3::Zero()));
                 });

    // Applied moments about fixed axes: potential -lambda M theta_u(q)
    // (Lestringant & Kochmann eq. 32-33).
    for (const AxisLoad &m : moments)
      {
        Eigen::Vector4d q;
        for (unsigned int c = 0; c < 4; ++c)
          q[c] = u[layout_->rotation_dof(m.junction, c)] + (c == 0);
        const RotationAngle angle = rotation_angle_about(m.axis, q);
        const double        scale = -load_factor * m.value;
        LocalContribution   copy;
        copy.energy = scale * angle.angle;
        if (with_gradient)
          {
            const Eigen::Vector4d gradient = scale * angle.gradient;
            const Eigen::Matrix4d hessian  = scale * angle.hessian;
            store<4>(gradient, with_hessian ? &hessian : nullptr, copy);
            for (unsigned int c = 0; c < 4; ++c)
              copy.dofs.push_back(layout_->rotation_dof(m.junction, c));
          }
        copier(copy);
      }

    // Unused DoFs of rod ends at junctions appear in no stencil; outside
    // the direct path, give their (constrained) rows a diagonal entry.
    if (!direct && with_hessian && apply_constraints)
      for (const auto &unused : layout_->shared_copies())
        {
          LocalContribution copy;
          copy.matrix.reinit(1, 1);
          copy.matrix(0, 0) = 1.0;
          copy.vector.reinit(1);
          copy.dofs = {unused.first};
          copier(copy);
        }

    const auto &segments = layout_->segments();
    dealii::WorkStream::run(
      segments.begin(),
      segments.end(),
      [&](const std::vector<SegmentStencil>::const_iterator &it,
          Scratch                                           &scratch,
          LocalContribution                                 &copy) {
        copy.dofs.clear();
        copy.energy = 0;
        guarded([&] {
          const double l0 = configuration_->rest_length(it->cell);
          evaluate_stretch(configuration_->segment_dofs(u, *it),
                           l0,
                           scratch.stretch,
                           with_hessian);
          const MaterialResponse<1> w = materials[it->rod]->segment_increment(
            scratch.stretch.strain,
            l0,
            history.block(InternalVariables::Owner::segment,
                          it - segments.begin()),
            step_length,
            nullptr);
          copy.energy = w.energy;
          if (!with_gradient)
            return;
          const SegmentVector gradient = w.stress[0] * scratch.stretch.gradient;
          SegmentMatrix       hessian;
          if (with_hessian)
            hessian = w.tangent(0, 0) * scratch.stretch.gradient *
                        scratch.stretch.gradient.transpose() +
                      w.stress[0] * scratch.stretch.hessian;
          store<n_segment_dofs>(gradient,
                                with_hessian ? &hessian : nullptr,
                                copy);
          copy.dofs.assign(it->dofs.begin(), it->dofs.end());
        });
      },
      copier,
      Scratch(),
      LocalContribution());

    if (failure)
      std::rethrow_exception(failure);

    // Dead loads: potential -lambda f.x, with x = X + u; the constant
    // f.X does not change any derivative and is dropped.
    energy -= load_factor * (f_ext * u);
    if (extra_force != nullptr)
      energy -= *extra_force * u;
    if (residual != nullptr)
      {
        residual->compress(dealii::VectorOperation::add);
        residual->add(-load_factor, f_ext);
        if (extra_force != nullptr)
          residual->add(-1.0, *extra_force);
        constraints.set_zero(*residual);
      }
    if (tangent != nullptr)
      {
        if (direct)
          scatter.finish();
        tangent->compress(dealii::VectorOperation::add);
      }
    return energy;
  }

  double
  RodModel::elastic_energy(const VectorType &u) const
  {
    return assemble(u, 0.0, nullptr, nullptr);
  }
} // namespace rodnet
