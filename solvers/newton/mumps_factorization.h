#ifndef RODNET_SOLVERS_NEWTON_MUMPS_FACTORIZATION_H
#define RODNET_SOLVERS_NEWTON_MUMPS_FACTORIZATION_H

#include <solvers/newton/tangent_factorization.h>

#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * MUMPS (Amestoy, Duff, L'Excellent & Koster, SIAM J. Matrix Anal. Appl.
   * 23, 2001), the multifrontal direct solver, through its C interface
   * (dmumps_c), as the LDL^T of a symmetric indefinite tangent (SYM = 2):
   * MUMPS is given the lower triangle and pivots in 1 x 1 and 2 x 2 blocks,
   * delaying a pivot that is too small to a later front. Its fronts are
   * dense blocks factorized by BLAS 3, where KLU, which has no supernodes,
   * works entry by entry (doc/performance.md, "MUMPS against KLU on welded
   * lattices").
   *
   * The analysis (the fill-reducing order and the tree of fronts) is done
   * once, at construction, on the pattern alone (no matching or compressed
   * graph from values, ICNTL(6) = 0, ICNTL(12) = 1): the matrix may hold no
   * values yet, and a factorization kept for the pattern
   * (TangentFactorizationCache) reuses it. The order is AMF, approximate
   * minimum fill (ICNTL(7) = 2): Debian's MUMPS 5.5 is built without METIS
   * and SCOTCH (a request for METIS falls back to PORD), and on the welded
   * lattice AMF's factorization took 16 % fewer flops than AMD's and QAMD's
   * and 24 % fewer than PORD's at 5.8e5 DoFs, 16 % fewer than AMD's at
   * 1.1e6, for 1-3 % more entries (doc/performance.md). Rows and columns
   * are scaled by the diagonal at each factorization (ICNTL(8) = 1).
   *
   * One process for now, the matrix centralized on it; the communicator is
   * the matrix's, so that the distributed input of MUMPS (ICNTL(18) = 3,
   * each process giving its rows) can follow without changing the
   * interface. MUMPS prints nothing. A failure of MUMPS's (INFOG(1) < 0) is
   * a std::runtime_error that names MUMPS and says what happened; where its
   * work space was too small (-8, -9), the factorization is retried once
   * with twice the space (ICNTL(14)).
   */
  class MumpsFactorization : public TangentFactorization
  {
  public:
    /// Analyses the pattern of @p matrix, which must live on one process
    /// (std::invalid_argument otherwise) and keep its pattern.
    explicit MumpsFactorization(const MatrixType &matrix);

    ~MumpsFactorization() override;

    MumpsFactorization(const MumpsFactorization &) = delete;
    MumpsFactorization &
    operator=(const MumpsFactorization &) = delete;

    /// Factorizes the matrix's current values; std::logic_error where its
    /// number of entries changed since the analysis.
    void
    factorize() override;

    using TangentFactorization::solve;

    void
    solve(const VectorType &b, VectorType &x) override;

    /// Both columns in one call of MUMPS's solve.
    void
    solve(const VectorType &b,
          VectorType       &x,
          const VectorType &c,
          VectorType       &y) override;

    /// "mumps".
    std::string
    name() const override;

    /// The entries of the factors (INFOG(29)): those of L and of the
    /// blocks of D, the upper triangle not stored. So it counts about half
    /// of what KLU's L and U of the same matrix do.
    double
    factor_entries() const override;

    /// The number of negative pivots of the last factorization (INFOG(12)):
    /// by Sylvester's law of inertia the number of negative eigenvalues of
    /// the matrix, where it is regular. 0 before the first factorization.
    unsigned int
    negative_pivots() const;

    /// The fill-reducing order the analysis took (INFOG(7)), e.g. "AMD".
    std::string
    ordering() const;

  private:
    /// Calls MUMPS with @p job (1 analysis, 2 factorization, 3 solve) and
    /// throws std::runtime_error, naming @p what was done, where it fails.
    void
    run(int job, const std::string &what);

    /// Solves the @p n_columns columns of rhs in place.
    void
    solve_columns(int n_columns);

    /// MUMPS's instance (dmumps_c's structure, kept out of this header).
    struct Instance;
    std::unique_ptr<Instance> mumps;

    const MatrixType &matrix;
    /// The lower triangle in coordinates from 1, as MUMPS reads it, and its
    /// values, copied at each factorize().
    std::vector<int>    rows, columns;
    std::vector<double> values;
    /// The right-hand sides, which MUMPS overwrites with the solutions.
    std::vector<double> rhs;
    bool                factorized = false;
  };
} // namespace rodnet

#endif
