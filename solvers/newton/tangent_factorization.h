#ifndef RODNET_SOLVERS_NEWTON_TANGENT_FACTORIZATION_H
#define RODNET_SOLVERS_NEWTON_TANGENT_FACTORIZATION_H

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace rodnet
{
  /**
   * Thrown by TangentFactorization::factorize() where the solver finds the
   * tangent singular (a zero pivot), as distinct from its other failures
   * (work space, memory): a caller that steps past a singular point catches
   * this one only.
   */
  class SingularTangent : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The direct solver of Newton's linear systems K x = b with the tangent
   * K: factorized once per Newton iteration, then used for one or more
   * solves. Three kinds:
   *  - "klu": SuiteSparse KLU, sparse LU for any pattern; its symbolic
   *    analysis (the fill-reducing order) is done once, at construction,
   *    and its pivots stay on the diagonal, where that order wants them,
   *    unless the diagonal is tiny (make_klu_factorization()). One process
   *    only.
   *  - "band": LAPACK's band LU with partial pivoting (dgbtrf, dgbtrs) on
   *    the tangent's band. A rod's DoFs are numbered along it, so its
   *    tangent is a narrow band (half-width 11 for one rod), which the
   *    band LU factorizes 4-5 times faster than KLU (doc/performance.md);
   *    a network's junction DoFs come last and widen the band. One process
   *    only.
   *  - "mumps": MUMPS's multifrontal LDL^T of the symmetric tangent
   *    (MumpsFactorization), its analysis done at construction; on the
   *    welded lattice its factorization is 2-3 times faster than KLU's
   *    from 5.8e5 DoFs (doc/performance.md). On several processes too,
   *    each giving MUMPS its rows: the distributed direct solver.
   * "auto" takes the band where its half-widths are at most
   * max_auto_band_width, as numbered or renumbered by reverse Cuthill-McKee
   * (the multipliers of inextensible rods come after all other DoFs: a
   * rod's KKT tangent is a narrow band once they sit next to their
   * segments, and KLU's fill on its zero diagonal grows fast); otherwise KLU
   * below min_auto_mumps_rows rows and MUMPS from there (doc/performance.md:
   * MUMPS's wall time against KLU's 0.99 at 1.2e4 DoFs, 0.97 at 3.8e4, 0.72
   * at 3.3e5); on a matrix of several processes "auto" takes MUMPS. "band"
   * renumbers where that narrows the band.
   */
  class TangentFactorization
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;
    using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

    virtual ~TangentFactorization() = default;

    /// The largest lower or upper half-width of the band for which "auto"
    /// takes the band LU.
    static constexpr int max_auto_band_width = 32;

    /// The fewest rows for which "auto" takes MUMPS rather than KLU, where
    /// the band is wide.
    static constexpr int min_auto_mumps_rows = 30000;

    /**
     * A factorization of the matrices of @p matrix's pattern (its values
     * are read at each factorize()): @p kind "klu", "band", "mumps" or
     * "auto". Its construction (the symbolic analysis), factorize() and
     * solves are timed as phases of base/phase_times.h. Throws
     * std::invalid_argument for another kind, and for "klu" and "band" on more
     * than one process (naming "mumps", which runs there).
     */
    static std::unique_ptr<TangentFactorization>
    create(const MatrixType &matrix, const std::string &kind);

    /// The kinds create() makes, as a deal.II selection pattern's list.
    static constexpr const char *kinds = "auto|klu|band|mumps";

    /// Throws std::invalid_argument, listing the kinds, unless @p kind is
    /// one that create() makes.
    static void
    check_kind(const std::string &kind);

    /// Factorizes the matrix's current values. Throws SingularTangent,
    /// naming the solver, where the matrix is singular, and
    /// std::runtime_error for the solver's other failures.
    virtual void
    factorize() = 0;

    /// Solves K x = b with the last factorization.
    virtual void
    solve(const VectorType &b, VectorType &x) = 0;

    /// Solves K x = b and K y = c with the last factorization, the same
    /// values as two solve() calls; KLU takes both in one pass over its
    /// factors (the midpoint rule's Sherman-Morrison solve beside Newton's).
    virtual void
    solve(const VectorType &b,
          VectorType       &x,
          const VectorType &c,
          VectorType       &y)
    {
      solve(b, x);
      solve(c, y);
    }

    /// "klu", "band" or "mumps".
    virtual std::string
    name() const = 0;

    /// The entries the last factorization stores: those of KLU's L and U
    /// (their diagonals included), of MUMPS's L and D (one triangle, all
    /// processes' together), or the band as LAPACK stores it; 0 before the
    /// first factorization.
    virtual double
    factor_entries() const = 0;

    /// The number of negative pivots of the last factorization, where it
    /// is an LDL^T that counts them (MUMPS): by Sylvester's law of inertia
    /// the number of negative eigenvalues of a regular matrix. std::nullopt
    /// for an LU (KLU, the band), whose pivots do not give the inertia.
    virtual std::optional<unsigned int>
    negative_pivots() const
    {
      return std::nullopt;
    }

  private:
    /// The factorization create() returns, before it is wrapped to time
    /// its phases (base/phase_times.h); @p kind is checked.
    static std::unique_ptr<TangentFactorization>
    make_factorization(const MatrixType &matrix, const std::string &kind);
  };

  /**
   * A tangent's factorization kept from one Newton solve to the next (load
   * steps, time steps, the rounds of one step): KLU's symbolic analysis
   * and the band's width and places are found once for as long as the
   * tangent is the same matrix with the same pattern. The pattern is
   * compared by a fingerprint of its compressed rows at each get(); on
   * several processes each compares its own rows, and all make a new
   * factorization together where one of them changed (get() is collective
   * there). A kept MUMPS factorization also serves a request for "mumps"
   * where it was made for "auto" (and the reverse on several processes,
   * where "auto" is MUMPS): the equilibrium checks ask for MUMPS on the
   * Newton solver's cache and reuse its analysis
   * (EquilibriumFactorization).
   */
  class TangentFactorizationCache
  {
  public:
    using MatrixType = TangentFactorization::MatrixType;

    /// TangentFactorization::create(@p matrix, @p kind), or the kept one
    /// if it was made for the same matrix, pattern and kind.
    std::shared_ptr<TangentFactorization>
    get(const MatrixType &matrix, const std::string &kind);

  private:
    /// Whether the kept factorization is what a request for @p kind on
    /// @p n_processes processes would make.
    bool
    serves(const std::string &kind, unsigned int n_processes) const;

    std::shared_ptr<TangentFactorization> factorization;
    const void                           *matrix  = nullptr;
    std::uint64_t                         pattern = 0;
    std::string                           kind;
  };
} // namespace rodnet

#endif
