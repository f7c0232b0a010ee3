#ifndef RODNET_SOLVERS_NEWTON_MUMPS_FACTORIZATION_H
#define RODNET_SOLVERS_NEWTON_MUMPS_FACTORIZATION_H

#include <solvers/newton/host_gather.h>
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
   * MUMPS runs on the matrix's communicator. On several processes each
   * gives MUMPS the lower triangle of the rows it owns (distributed
   * assembled input, ICNTL(18) = 3); on one the matrix is centralized
   * (ICNTL(18) = 0), as before there was distributed input. The right-hand
   * sides are gathered onto the host (rank 0) and the solutions scattered
   * back into the rows each process owns (HostGather): MUMPS's distributed
   * solution (ICNTL(21) = 1) would come out spread as MUMPS's fronts are,
   * not as the matrix's rows, and need an exchange between all processes
   * to be put back, where the gather is one message from each process to
   * the host, small beside the factorization (8 bytes a DoF, where the
   * factors of the welded lattice hold 25 entries a DoF and cost 3000 to
   * 4500 flops a DoF). MUMPS's global information (INFOG, section
   * "information available on all processors" of its user guide) is on
   * every process, so negative_pivots(), factor_entries() and its failures
   * are the same on every process.
   *
   * MUMPS prints nothing. A failure of MUMPS's (INFOG(1) < 0) is a
   * std::runtime_error, thrown on every process, that names MUMPS and says
   * what happened; where its work space was too small (-8, -9), the
   * factorization is retried with twice the space (ICNTL(14)), up to three
   * times.
   * The constructor, factorize() and the solves are collective: every
   * process calls them.
   */
  class MumpsFactorization : public TangentFactorization
  {
  public:
    /// Analyses the pattern of @p matrix, which must keep its pattern.
    explicit MumpsFactorization(const MatrixType &matrix);

    ~MumpsFactorization() override;

    MumpsFactorization(const MumpsFactorization &) = delete;
    MumpsFactorization &
    operator=(const MumpsFactorization &) = delete;

    /// Factorizes the matrix's current values; std::logic_error, on every
    /// process, where the number of entries of a process's rows changed
    /// since the analysis.
    void
    factorize() override;

    using TangentFactorization::solve;

    void
    solve(const VectorType &b, VectorType &x) override;

    /// Both columns in one call of MUMPS's solve. The vectors must be
    /// distributed as the matrix's rows (std::invalid_argument otherwise).
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
    std::optional<unsigned int>
    negative_pivots() const override;

    /// The fill-reducing order the analysis took (INFOG(7)), e.g. "AMD".
    std::string
    ordering() const;

  private:
    /// Calls MUMPS with @p job (1 analysis, 2 factorization, 3 solve) and
    /// throws std::runtime_error, naming @p what was done, where it fails.
    void
    run(int job, const std::string &what);

    /// Solves K x = b for each of @p right_hand_sides into the
    /// @p solutions of the same place, in one call of MUMPS.
    void
    solve_columns(const std::vector<const VectorType *> &right_hand_sides,
                  const std::vector<VectorType *>       &solutions);

    /// Copies the matrix's values into values; false where the number of
    /// this process's lower-triangle entries changed since the analysis.
    bool
    copy_values();

    /// MUMPS's instance (dmumps_c's structure, kept out of this header).
    struct Instance;
    std::unique_ptr<Instance> mumps;

    const MatrixType &matrix;
    const MPI_Comm    communicator;
    /// The right-hand sides and solutions between the processes' rows and
    /// MUMPS's host.
    const HostGather host;
    /// The lower triangle of this process's rows in global coordinates from
    /// 1, as MUMPS reads it, and its values, copied at each factorize().
    std::vector<int>    rows, columns;
    std::vector<double> values;

    /// The right-hand sides, which MUMPS overwrites with the solutions, in
    /// columns of all rows on the host (empty elsewhere).
    std::vector<double> rhs;
    bool                factorized = false;
  };
} // namespace rodnet

#endif
