#include <deal.II/base/mpi.h>

#include <core/every_entry.h>
#include <solvers/checks/equilibrium_factorization.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// ConstrainedFactorization, the serial LDL^T of the free block, behind
    /// the checks' interface.
    class ReplicatedFactorization : public EquilibriumFactorization
    {
    public:
      ReplicatedFactorization(const SolvableModel &model,
                              const MatrixType    &tangent)
          : factorization(tangent,
                          model.constraints(),
                          0.0,
                          model.multiplier_dofs())
      {
      }

      Inertia
      inertia() const override
      {
        return factorization.inertia();
      }

      void
      solve(const VectorType &b, VectorType &x) const override
      {
        const EveryEntry    every_entry(b);
        const double       *values = (*every_entry).trilinos_vector()[0];
        std::vector<double> solution =
          factorization.solve(std::vector<double>(values, values + b.size()));
        for (const global_dof_index i : x.locally_owned_elements())
          x[i] = solution[i];
        x.compress(dealii::VectorOperation::insert);
      }

    private:
      const ConstrainedFactorization factorization;
    };

    /// MUMPS's distributed LDL^T of the KKT tangent (see
    /// EquilibriumFactorization).
    class DistributedFactorization : public EquilibriumFactorization
    {
    public:
      DistributedFactorization(const SolvableModel       &model,
                               const MatrixType          &tangent,
                               TangentFactorizationCache *factorizations);

      Inertia
      inertia() const override;

      void
      solve(const VectorType &b, VectorType &x) const override;

    private:
      /// Zeroes the entries of @p v at this process's held rows.
      void
      zero_held_rows(VectorType &v) const;

      std::shared_ptr<TangentFactorization> factorization;
      /// This process's rows of fixed DoFs and of multipliers.
      std::vector<global_dof_index> held_rows;
      /// The multipliers and the DoFs on the constraint manifold, over all
      /// processes.
      unsigned int n_multipliers = 0;
      unsigned int n_free        = 0;
      /// Whether MUMPS met a zero pivot.
      bool singular = false;
    };

    DistributedFactorization::DistributedFactorization(
      const SolvableModel       &model,
      const MatrixType          &tangent,
      TangentFactorizationCache *factorizations)
        : factorization(factorizations ?
                          factorizations->get(tangent, "mumps") :
                          TangentFactorization::create(tangent, "mumps"))
    {
      const dealii::IndexSet owned = tangent.locally_owned_range_indices();
      const auto            &constraints     = model.constraints();
      unsigned int           own_multipliers = 0;
      for (const global_dof_index i : owned)
        if (constraints.is_constrained(i))
          held_rows.push_back(i);
      for (const global_dof_index d : model.multiplier_dofs())
        if (owned.is_element(d) && !constraints.is_constrained(d))
          {
            held_rows.push_back(d);
            ++own_multipliers;
          }
      const MPI_Comm comm = tangent.get_mpi_communicator();
      n_multipliers       = dealii::Utilities::MPI::sum(own_multipliers, comm);
      n_free =
        tangent.m() -
        dealii::Utilities::MPI::sum(static_cast<unsigned int>(held_rows.size()),
                                    comm);
      try
        {
          factorization->factorize();
        }
      catch (const SingularTangent &)
        {
          singular = true;
        }
    }

    Inertia
    DistributedFactorization::inertia() const
    {
      Inertia result;
      if (singular)
        {
          result.zero          = 1;
          result.weakest_ratio = 0;
          result.weakest_dof   = dealii::numbers::invalid_unsigned_int;
          return result;
        }
      // One negative pivot per multiplier besides those of Z^T H Z.
      const unsigned int pivots = factorization->negative_pivots().value();
      result.negative           = pivots - std::min(pivots, n_multipliers);
      result.positive           = n_free - std::min(n_free, result.negative);
      return result;
    }

    void
    DistributedFactorization::zero_held_rows(VectorType &v) const
    {
      for (const global_dof_index i : held_rows)
        v[i] = 0;
      v.compress(dealii::VectorOperation::insert);
    }

    void
    DistributedFactorization::solve(const VectorType &b, VectorType &x) const
    {
      if (singular)
        throw std::runtime_error("the tangent is singular");
      VectorType rhs = b;
      zero_held_rows(rhs);
      factorization->solve(rhs, x);
      zero_held_rows(x);
      if (!std::isfinite(x.l2_norm()))
        throw std::runtime_error("the tangent is singular");
    }
  } // namespace

  std::unique_ptr<EquilibriumFactorization>
  EquilibriumFactorization::create(const SolvableModel       &model,
                                   const MatrixType          &tangent,
                                   TangentFactorizationCache *factorizations)
  {
    const MPI_Comm comm = tangent.get_mpi_communicator();
    if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
      return std::make_unique<DistributedFactorization>(model,
                                                        tangent,
                                                        factorizations);
    return std::make_unique<ReplicatedFactorization>(model, tangent);
  }
} // namespace rodnet
