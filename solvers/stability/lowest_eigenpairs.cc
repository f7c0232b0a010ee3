#include <base/phase_times.h>
#include <solvers/solver_failure.h>
#include <solvers/stability/lowest_eigenpairs.h>
#include <solvers/stability/stability.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace rodnet
{
  using dealii::types::global_dof_index;

  namespace
  {
    /// Ritz pairs of the shift-inverted operator (K_ff - sigma I)^-1, over
    /// the free DoFs.
    struct RitzPairs
    {
      Eigen::VectorXd theta;
      Eigen::MatrixXd vectors;
    };

    /// Which Ritz values a Lanczos run converges: the largest (a positive
    /// definite operator, sigma below the spectrum) or the largest in
    /// magnitude (the eigenvalue nearest sigma, of either sign).
    enum class Wanted
    {
      largest,
      largest_magnitude
    };

    /**
     * Orthonormalizes the columns of @p w against the @p used columns of
     * @p q (twice: classical Gram-Schmidt loses orthogonality to rounding
     * once) and among themselves by a QR factorization. A column in the
     * span of the others (the Krylov space is invariant) is replaced by a
     * random one, orthogonal to all, with a zero column of R. Returns R,
     * the coupling of the new block to the last one.
     */
    Eigen::MatrixXd
    orthonormalize(Eigen::MatrixXd       &w,
                   const Eigen::MatrixXd &q,
                   const Eigen::Index     used,
                   std::mt19937          &random)
    {
      const auto project_out = [&](Eigen::MatrixXd &block) {
        for (int pass = 0; pass < 2; ++pass)
          block -= q.leftCols(used) * (q.leftCols(used).transpose() * block);
      };
      project_out(w);
      const Eigen::Index                    b = w.cols();
      Eigen::HouseholderQR<Eigen::MatrixXd> qr(w);
      Eigen::MatrixXd                       r =
        qr.matrixQR().topRows(b).triangularView<Eigen::Upper>();
      w = qr.householderQ() * Eigen::MatrixXd::Identity(w.rows(), b);
      const double scale = std::max(r.cwiseAbs().maxCoeff(), 1e-300);
      std::normal_distribution<double> normal;
      for (Eigen::Index j = 0; j < b; ++j)
        if (std::abs(r(j, j)) < 1e-12 * scale)
          {
            Eigen::MatrixXd fresh(w.rows(), 1);
            for (Eigen::Index i = 0; i < w.rows(); ++i)
              fresh(i, 0) = normal(random);
            project_out(fresh);
            for (Eigen::Index c = 0; c < b; ++c)
              if (c != j)
                fresh -= w.col(c) * (w.col(c).dot(fresh.col(0)));
            w.col(j) = fresh.col(0).normalized();
            r.row(j).setZero();
          }
      return r;
    }

    /// Indices of the @p wanted Ritz values of @p theta first.
    std::vector<Eigen::Index>
    order_of(const Eigen::VectorXd &theta, const Wanted wanted)
    {
      std::vector<Eigen::Index> order(theta.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](auto a, auto b) {
        return wanted == Wanted::largest ?
                 theta[a] > theta[b] :
                 std::abs(theta[a]) > std::abs(theta[b]);
      });
      return order;
    }

    /// Whether the residual |R s_last| of each of the first @p count Ritz
    /// pairs of @p order (s an eigenvector of T in @p ritz, s_last its last
    /// block, R the coupling @p r to the next block) is below
    /// @p tolerance |theta|.
    bool
    ritz_residuals_small(
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> &ritz,
      const std::vector<Eigen::Index>                      &order,
      const unsigned int                                    count,
      const Eigen::MatrixXd                                &r,
      const double                                          tolerance)
    {
      const Eigen::Index b = r.cols();
      for (unsigned int i = 0; i < count; ++i)
        {
          const double theta = ritz.eigenvalues()[order[i]];
          const double residual =
            (r * ritz.eigenvectors().col(order[i]).tail(b)).norm();
          if (!(residual <= tolerance * std::abs(theta)))
            return false;
        }
      return true;
    }

    /// The first @p count Ritz pairs of @p order: the eigenvalues theta of
    /// T in @p ritz and the vectors Q s over the basis @p q.
    RitzPairs
    ritz_pairs(const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> &ritz,
               const std::vector<Eigen::Index>                      &order,
               const unsigned int                                    count,
               const Eigen::MatrixXd                                &q)
    {
      RitzPairs pairs{Eigen::VectorXd(count), Eigen::MatrixXd(q.rows(), count)};
      for (unsigned int i = 0; i < count; ++i)
        {
          pairs.theta[i]       = ritz.eigenvalues()[order[i]];
          pairs.vectors.col(i) = q * ritz.eigenvectors().col(order[i]);
        }
      return pairs;
    }

    /**
     * Block Lanczos with full reorthogonalization on (K_ff - sigma I)^-1
     * (@p factorization): the Krylov basis Q grows by one block per solve
     * of @p block right-hand sides, T = Q^T A Q is kept whole (it is block
     * tridiagonal in exact arithmetic, and symmetrized against rounding),
     * and the run ends when the residual |A y - theta y| = |R s_last| of
     * each of the @p n wanted Ritz pairs (theta, y = Q s) is below
     * @p tolerance |theta|. Counts the solves into @p solves.
     */
    RitzPairs
    block_lanczos(const ConstrainedFactorization &factorization,
                  const unsigned int              n,
                  const unsigned int              block,
                  const double                    tolerance,
                  const Wanted                    wanted,
                  unsigned int                   &solves)
    {
      const Eigen::Index size = factorization.free_dofs().size();
      const Eigen::Index max_columns =
        std::min<Eigen::Index>(size, 10 * Eigen::Index(n) + 100);
      const Eigen::Index b = std::min<Eigen::Index>(block, size);
      std::mt19937       random(20261204);
      Eigen::MatrixXd    q(size, 0), t(0, 0);
      Eigen::MatrixXd    w = Eigen::MatrixXd::Zero(size, b);
      orthonormalize(w, q, 0, random); // a random start block
      while (true)
        {
          const Eigen::Index used = q.cols();
          q.conservativeResize(size, used + b);
          q.rightCols(b) = w;
          factorization.solve_free(w);
          solves += b;
          // The new block's column of T, and its coupling to the next one.
          const Eigen::MatrixXd h = q.transpose() * w;
          w -= q * h;
          const Eigen::Index grown = used + b;
          Eigen::MatrixXd    r     = grown < size ?
                                       orthonormalize(w, q, grown, random) :
                                       Eigen::MatrixXd::Zero(b, b);
          t.conservativeResize(grown, grown);
          t.rightCols(b)            = h;
          t.bottomRows(b)           = h.transpose();
          const Eigen::MatrixXd sym = 0.5 * (t + t.transpose());
          const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(sym);
          const auto         order = order_of(ritz.eigenvalues(), wanted);
          const unsigned int count =
            std::min<Eigen::Index>(n, ritz.eigenvalues().size());
          const bool converged =
            grown >= std::min<Eigen::Index>(size, n) &&
            ritz_residuals_small(ritz, order, count, r, tolerance);
          if (converged || grown >= size)
            return ritz_pairs(ritz, order, count, q);
          if (grown + b > max_columns)
            throw SolverFailure("the sparse eigen-solver did not converge in " +
                                std::to_string(grown) + " Lanczos vectors");
        }
    }

    /// The free rows of @p tangent as a dense matrix; the free DoFs into
    /// @p global.
    Eigen::MatrixXd
    dense_free_block(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                     const dealii::AffineConstraints<double>      &constraints,
                     std::vector<unsigned int>                    &global)
    {
      std::vector<int> free_index(tangent.m(), -1);
      for (unsigned int i = 0; i < tangent.m(); ++i)
        if (!constraints.is_constrained(i))
          {
            free_index[i] = global.size();
            global.push_back(i);
          }
      Eigen::MatrixXd dense =
        Eigen::MatrixXd::Zero(global.size(), global.size());
      // Every row, also those of other processes.
      std::unique_ptr<Epetra_CrsMatrix> gathered;
      const Epetra_CrsMatrix           &matrix = every_row(tangent, gathered);
      for (const unsigned int i : global)
        {
          int     length;
          double *values;
          int    *columns;
          matrix.ExtractMyRowView(matrix.LRID(int(i)), length, values, columns);
          for (int e = 0; e < length; ++e)
            if (free_index[matrix.GCID(columns[e])] >= 0)
              dense(free_index[i], free_index[matrix.GCID(columns[e])]) =
                values[e];
        }
      return dense;
    }

    /// A dense free block [H, G^T; G, 0] split at its multipliers: H over
    /// the other free DoFs (@p space, global indices) and an orthonormal
    /// basis of the null space of G.
    struct ManifoldSplit
    {
      ManifoldSplit(const Eigen::MatrixXd               &dense,
                    const std::vector<unsigned int>     &global,
                    const std::vector<global_dof_index> &multipliers)
      {
        std::vector<Eigen::Index> rows, constraint_rows;
        for (std::size_t k = 0; k < global.size(); ++k)
          if (std::find(multipliers.begin(), multipliers.end(), global[k]) ==
              multipliers.end())
            {
              rows.push_back(k);
              space.push_back(global[k]);
            }
          else
            constraint_rows.push_back(k);
        hessian                 = dense(rows, rows);
        const Eigen::MatrixXd g = dense(constraint_rows, rows);
        // Z: the last columns of Q in G^T P = Q R, beyond the rank of G.
        const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(g.transpose());
        const Eigen::MatrixXd                             q = qr.householderQ();
        null_space = q.rightCols(rows.size() - qr.rank());
      }

      std::vector<unsigned int> space;
      Eigen::MatrixXd           hessian;
      Eigen::MatrixXd           null_space;
    };

    /// Appends the eigenpairs (@p values[i], column i of @p vectors over
    /// the free DoFs @p global) to @p pairs, the vectors over all
    /// @p n_dofs DoFs.
    void
    append(Eigenpairs                      &pairs,
           const Eigen::VectorXd           &values,
           const Eigen::MatrixXd           &vectors,
           const std::vector<unsigned int> &global,
           const unsigned int               n_dofs)
    {
      for (Eigen::Index i = 0; i < values.size(); ++i)
        {
          std::vector<double> vector(n_dofs, 0.0);
          const double        norm = vectors.col(i).norm();
          for (std::size_t k = 0; k < global.size(); ++k)
            vector[global[k]] = vectors(k, i) / norm;
          pairs.values.push_back(values[i]);
          pairs.vectors.push_back(std::move(vector));
        }
    }

    /// The factorization of K_ff - sigma I, counted into @p pairs.
    std::unique_ptr<ConstrainedFactorization>
    factorize(const dealii::TrilinosWrappers::SparseMatrix &tangent,
              const dealii::AffineConstraints<double>      &constraints,
              const std::vector<global_dof_index>          &multipliers,
              const double                                  sigma,
              Eigenpairs                                   &pairs)
    {
      ++pairs.factorizations;
      return std::make_unique<ConstrainedFactorization>(tangent,
                                                        constraints,
                                                        sigma,
                                                        multipliers);
    }

    /**
     * A factorization of K_ff - sigma I with sigma below every eigenvalue
     * of K_ff (doc of lowest_eigenpairs(), step 1), into @p sigma.
     */
    std::unique_ptr<ConstrainedFactorization>
    positive_definite_shift(
      const dealii::TrilinosWrappers::SparseMatrix &tangent,
      const dealii::AffineConstraints<double>      &constraints,
      const std::vector<global_dof_index>          &multipliers,
      const double                                  tolerance,
      double                                       &sigma,
      Eigenpairs                                   &pairs)
    {
      sigma = 0;
      auto factorization =
        factorize(tangent, constraints, multipliers, sigma, pairs);
      if (factorization->positive_definite())
        return factorization;
      // A singular K_ff (a zero pivot) is shifted off its null space by an
      // amount at the rounding of its entries.
      if (factorization->inertia().zero > 0)
        {
          sigma = -1e-10 * factorization->diagonal_scale();
          factorization =
            factorize(tangent, constraints, multipliers, sigma, pairs);
          if (factorization->inertia().zero > 0)
            throw SolverFailure(
              "the sparse eigen-solver cannot factorize the tangent");
          if (factorization->positive_definite())
            return factorization;
        }
      const double nearest = block_lanczos(*factorization,
                                           1,
                                           3,
                                           tolerance,
                                           Wanted::largest_magnitude,
                                           pairs.solves)
                               .theta[0];
      const double start    = sigma;
      double       distance = 2 / std::abs(nearest);
      for (unsigned int trial = 0; trial < 40; ++trial, distance *= 4)
        {
          sigma = start - distance;
          factorization =
            factorize(tangent, constraints, multipliers, sigma, pairs);
          if (factorization->positive_definite())
            return factorization;
        }
      throw SolverFailure("the sparse eigen-solver found no shift below "
                          "the tangent's eigenvalues");
    }

    /// The size of the eigen-space: the free DoFs but the multipliers.
    unsigned int
    eigenspace_size(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                    const dealii::AffineConstraints<double>      &constraints,
                    const std::vector<global_dof_index>          &multipliers)
    {
      unsigned int n_free = 0;
      for (unsigned int i = 0; i < tangent.m(); ++i)
        n_free += !constraints.is_constrained(i);
      for (const global_dof_index d : multipliers)
        n_free -= !constraints.is_constrained(d);
      return n_free;
    }

    /// How many eigenvalues of K_ff lie below @p tau: the negative inertia
    /// of K_ff - tau I (doc of lowest_eigenpairs(), step 3).
    unsigned int
    eigenvalues_below(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                      const dealii::AffineConstraints<double>      &constraints,
                      const std::vector<global_dof_index>          &multipliers,
                      const double                                  tau,
                      Eigenpairs                                   &pairs)
    {
      return factorize(tangent, constraints, multipliers, tau, pairs)
        ->inertia(0.0)
        .negative;
    }
  } // namespace

  Eigenpairs
  dense_eigenpairs(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                   const dealii::AffineConstraints<double>      &constraints,
                   const unsigned int                            k,
                   const std::vector<global_dof_index>          &multipliers)
  {
    std::vector<unsigned int> global;
    Eigen::MatrixXd dense = dense_free_block(tangent, constraints, global);
    // On the constraint manifold: H reduced to an orthonormal basis Z of
    // the null space of the multipliers' rows G (Nocedal & Wright 16.2).
    Eigen::MatrixXd basis;
    if (!multipliers.empty())
      {
        const ManifoldSplit split(dense, global, multipliers);
        basis  = split.null_space;
        dense  = basis.transpose() * split.hessian * basis;
        global = split.space;
      }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense);
    if (solver.info() != Eigen::Success)
      throw SolverFailure("the dense eigenvalue solver did not converge");
    const Eigen::Index count = std::min<Eigen::Index>(k, dense.rows());
    Eigenpairs         pairs; // Eigen's eigenvalues increase
    append(pairs,
           solver.eigenvalues().head(count),
           multipliers.empty() ?
             Eigen::MatrixXd(solver.eigenvectors().leftCols(count)) :
             Eigen::MatrixXd(basis * solver.eigenvectors().leftCols(count)),
           global,
           tangent.m());
    return pairs;
  }


  Eigenpairs
  lowest_eigenpairs(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                    const dealii::AffineConstraints<double>      &constraints,
                    const unsigned int                            k,
                    const std::vector<global_dof_index>          &multipliers,
                    const double                                  tolerance)
  {
    const phase_times::Scope phase(phase_times::Phase::checks);
    const unsigned int       n_free =
      eigenspace_size(tangent, constraints, multipliers);
    if (n_free == 0)
      throw std::invalid_argument("every DoF is constrained: no eigenpair");
    // The dense solver also where k is a fair part of the spectrum: the
    // Lanczos basis would be as large as the space.
    if (n_free <= max_dense_eigenpair_dofs || 4 * k >= n_free || k == 0)
      return dense_eigenpairs(tangent, constraints, k, multipliers);

    Eigenpairs   pairs;
    double       sigma         = 0;
    const auto   factorization = positive_definite_shift(tangent,
                                                       constraints,
                                                       multipliers,
                                                       tolerance,
                                                       sigma,
                                                       pairs);
    unsigned int wanted        = std::min(k, n_free);
    unsigned int block         = std::clamp(wanted, 3u, 6u);
    for (unsigned int attempt = 0;; ++attempt, block *= 2)
      {
        const RitzPairs ritz = block_lanczos(*factorization,
                                             wanted,
                                             block,
                                             tolerance,
                                             Wanted::largest,
                                             pairs.solves);
        // theta decreases, lambda = sigma + 1 / theta increases.
        const Eigen::VectorXd lambda =
          (sigma + ritz.theta.array().inverse()).matrix();
        // Step 3: as many eigenvalues below tau as were found below it.
        const double tau =
          lambda[wanted - 1] + 1e-6 * (lambda[wanted - 1] - sigma);
        const unsigned int below =
          eigenvalues_below(tangent, constraints, multipliers, tau, pairs);
        if (below <= wanted || wanted == n_free)
          {
            const unsigned int count = std::min(k, wanted);
            append(pairs,
                   lambda.head(count),
                   ritz.vectors.leftCols(count),
                   factorization->free_dofs(),
                   tangent.m());
            return pairs;
          }
        if (attempt == 2)
          throw SolverFailure(
            "the sparse eigen-solver misses eigenvalues of multiplicity "
            "above " +
            std::to_string(block));
        wanted = std::min(below, n_free);
      }
  }
} // namespace rodnet
