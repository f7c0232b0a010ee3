#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_index_access.h>

#include <solvers/newton/mumps_factorization.h>

#include <dmumps_c.h>
#include <stdexcept>
#include <type_traits>

namespace rodnet
{
  static_assert(std::is_same_v<MUMPS_INT, int>,
                "rodnet passes MUMPS 32-bit indices");

  /// MUMPS's instance, ended (JOB = -2) with the object, also where the
  /// constructor throws after starting it.
  struct MumpsFactorization::Instance
  {
    DMUMPS_STRUC_C id      = {};
    bool           started = false;

    ~Instance()
    {
      if (started)
        {
          id.job = -2;
          dmumps_c(&id);
        }
    }
  };

  namespace
  {
    /// How often a factorization short of work space is retried, each time
    /// with twice MUMPS's relaxation ICNTL(14).
    constexpr int max_space_retries = 5;

    /// MUMPS's ICNTL(i), INFOG(i) and the like, numbered from 1 as in its
    /// user guide.
    constexpr int
    mumps_index(const int i)
    {
      return i - 1;
    }

    /// A count that MUMPS gives in millions where it is negative
    /// (INFOG(29)).
    double
    mumps_count(const int value)
    {
      return value < 0 ? -1e6 * value : double(value);
    }

    /// What MUMPS's error code @p infog1 (INFOG(1) < 0, with INFOG(2) =
    /// @p infog2) means, in words (MUMPS 5.5 user guide, section 8).
    std::string
    mumps_error(const int infog1, const int infog2)
    {
      const std::string code = " (MUMPS: INFOG(1) = " + std::to_string(infog1) +
                               ", INFOG(2) = " + std::to_string(infog2) + ")";
      switch (infog1)
        {
          case -10:
            return "the tangent is singular (MUMPS found a zero pivot)" + code;
          case -8:
          case -9:
          case -14:
          case -15:
            return "MUMPS's work space was too small even after raising "
                   "it (ICNTL(14))" +
                   code;
          case -13:
            return "MUMPS could not allocate its memory" + code;
          case -16:
            return "MUMPS was given a matrix of no rows" + code;
          default:
            return "MUMPS failed" + code;
        }
    }

    /// MUMPS's controls for rodnet's tangents (see MumpsFactorization).
    void
    configure_mumps(DMUMPS_STRUC_C &id)
    {
      // No output: error, diagnostic and statistics streams closed.
      for (const int stream : {1, 2, 3})
        id.icntl[mumps_index(stream)] = -1;
      id.icntl[mumps_index(4)] = 0;
      id.icntl[mumps_index(5)] = 0; // assembled matrix
      // The analysis sees the pattern only: no matching, no compressed graph.
      id.icntl[mumps_index(6)]  = 0;
      id.icntl[mumps_index(12)] = 1;
      id.icntl[mumps_index(7)]  = 2; // AMF (see the class documentation)
      // Rows and columns scaled by the diagonal, computed at each
      // factorization: the tangent's diagonal spans stretching to bending
      // rigidities. On a flat welded lattice (83820 DoFs, AMD's order)
      // MUMPS's automatic choice (77) left |K x - b| / |b| = 7e-7, this one
      // 1.5e-11 (KLU, rows scaled: 6.6e-11).
      id.icntl[mumps_index(8)] = 1;
      // The root front by MUMPS itself, not ScaLAPACK, whose pivots INFOG(12)
      // does not count: the inertia stays right on several processes.
      id.icntl[mumps_index(13)] = 1;
    }

    /// Hands MUMPS the entries of the lower triangle, @p rows, @p columns
    /// (global, from 1) and @p values: centralized where there is one
    /// process, so that its results are those of the one-process code before
    /// distributed input (ICNTL(18) = 0), each process's own rows otherwise
    /// (distributed assembled input, ICNTL(18) = 3, the pattern read at the
    /// analysis and the values at each factorization).
    void
    hand_over_entries(DMUMPS_STRUC_C      &id,
                      const bool           distributed,
                      std::vector<int>    &rows,
                      std::vector<int>    &columns,
                      std::vector<double> &values)
    {
      id.icntl[mumps_index(18)] = distributed ? 3 : 0;
      if (distributed)
        {
          id.nnz_loc = rows.size();
          id.irn_loc = rows.data();
          id.jcn_loc = columns.data();
          id.a_loc   = values.data();
        }
      else
        {
          id.nnz = rows.size();
          id.irn = rows.data();
          id.jcn = columns.data();
          id.a   = values.data();
        }
    }

    /// Calls @p f(row, column, value), global indices from 0, for each
    /// stored entry of the lower triangle in the rows of @p m that this
    /// process owns, in the order of its compressed rows. The global indices
    /// are read from the maps' lists, not looked up entry by entry (GRID(),
    /// GCID(): two calls an entry took 3 % of each process's time on the
    /// welded lattice of 1.1e6 DoFs, doc/performance.md).
    template <class Function>
    void
    for_each_lower_entry(const Epetra_CrsMatrix &m, const Function &f)
    {
      const auto *row_gids =
        dealii::TrilinosWrappers::my_global_elements(m.RowMap());
      const auto *column_gids =
        dealii::TrilinosWrappers::my_global_elements(m.ColMap());
      for (int row = 0; row < m.NumMyRows(); ++row)
        {
          int     n;
          int    *local_columns;
          double *row_values;
          m.ExtractMyRowView(row, n, row_values, local_columns);
          const auto global_row = row_gids[row];
          for (int k = 0; k < n; ++k)
            if (const auto column = column_gids[local_columns[k]];
                column <= global_row)
              f(global_row, column, row_values[k]);
        }
    }
  } // namespace


  MumpsFactorization::MumpsFactorization(const MatrixType &matrix)
      : mumps(std::make_unique<Instance>())
      , matrix(matrix)
      , communicator(matrix.get_mpi_communicator())
      , host(matrix.trilinos_matrix().RowMap(), communicator)
  {
    for_each_lower_entry(matrix.trilinos_matrix(),
                         [&](const auto row, const auto column, double) {
                           rows.push_back(row + 1);
                           columns.push_back(column + 1);
                         });
    values.resize(rows.size());

    DMUMPS_STRUC_C &id = mumps->id;
    id.job             = -1;
    id.par             = 1; // the host process works too
    id.sym             = 2; // symmetric, indefinite
    id.comm_fortran    = MPI_Comm_c2f(communicator);
    dmumps_c(&id);
    mumps->started = id.infog[mumps_index(1)] >= 0;
    if (!mumps->started)
      throw std::runtime_error(
        "MUMPS could not start: " +
        mumps_error(id.infog[mumps_index(1)], id.infog[mumps_index(2)]));
    configure_mumps(id);
    id.n = matrix.m();
    hand_over_entries(id,
                      dealii::Utilities::MPI::n_mpi_processes(communicator) > 1,
                      rows,
                      columns,
                      values);
    run(1, "analysis");
  }


  MumpsFactorization::~MumpsFactorization() = default;


  void
  MumpsFactorization::run(const int job, const std::string &what)
  {
    DMUMPS_STRUC_C &id = mumps->id;
    id.job             = job;
    dmumps_c(&id);
    if (id.infog[mumps_index(1)] < 0)
      throw std::runtime_error(
        "MUMPS's " + what + " failed: " +
        mumps_error(id.infog[mumps_index(1)], id.infog[mumps_index(2)]));
  }


  bool
  MumpsFactorization::copy_values()
  {
    std::size_t k = 0;
    for_each_lower_entry(matrix.trilinos_matrix(),
                         [&](auto, auto, const double value) {
                           if (k < values.size())
                             values[k] = value;
                           ++k;
                         });
    return k == values.size();
  }


  void
  MumpsFactorization::factorize()
  {
    // Agreed by all processes: one that threw alone would leave the others
    // waiting in MUMPS.
    if (dealii::Utilities::MPI::logical_or(!copy_values(), communicator))
      throw std::logic_error(
        "the tangent's pattern changed after MUMPS's analysis of it");
    factorized         = false;
    DMUMPS_STRUC_C &id = mumps->id;
    id.job             = 2;
    dmumps_c(&id);
    // MUMPS's estimate of its work space falls short when delayed pivots grow
    // the fronts (an inextensible ring at its stress-free start needed 4x the
    // default relaxation, the snapping ribbon's KKT tangent on two processes
    // 16x): retried with twice the relaxation, up to 32x.
    for (int retry = 0;
         retry < max_space_retries &&
         (id.infog[mumps_index(1)] == -8 || id.infog[mumps_index(1)] == -9);
         ++retry)
      {
        id.icntl[mumps_index(14)] *= 2;
        dmumps_c(&id);
      }
    const int status = id.infog[mumps_index(1)];
    if (status == -10)
      throw SingularTangent("MUMPS's factorization failed: " +
                            mumps_error(status, id.infog[mumps_index(2)]));
    if (status < 0)
      throw std::runtime_error("MUMPS's factorization failed: " +
                               mumps_error(status, id.infog[mumps_index(2)]));
    factorized = true;
  }


  void
  MumpsFactorization::solve_columns(
    const std::vector<const VectorType *> &right_hand_sides,
    const std::vector<VectorType *>       &solutions)
  {
    for (unsigned int c = 0; c < right_hand_sides.size(); ++c)
      host.gather(*right_hand_sides[c], rhs, c);
    DMUMPS_STRUC_C &id = mumps->id;
    id.nrhs            = right_hand_sides.size();
    id.lrhs            = id.n;
    id.rhs             = rhs.data();
    run(3, "solve");
    for (unsigned int c = 0; c < solutions.size(); ++c)
      {
        *solutions[c] = *right_hand_sides[c];
        host.scatter(rhs, c, *solutions[c]);
      }
  }


  void
  MumpsFactorization::solve(const VectorType &b, VectorType &x)
  {
    solve_columns({&b}, {&x});
  }


  void
  MumpsFactorization::solve(const VectorType &b,
                            VectorType       &x,
                            const VectorType &c,
                            VectorType       &y)
  {
    solve_columns({&b, &c}, {&x, &y});
  }


  std::string
  MumpsFactorization::name() const
  {
    return "mumps";
  }


  double
  MumpsFactorization::factor_entries() const
  {
    return factorized ? mumps_count(mumps->id.infog[mumps_index(29)]) : 0.0;
  }


  std::optional<unsigned int>
  MumpsFactorization::negative_pivots() const
  {
    return factorized ? mumps->id.infog[mumps_index(12)] : 0;
  }


  std::string
  MumpsFactorization::ordering() const
  {
    switch (mumps->id.infog[mumps_index(7)])
      {
        case 0:
          return "AMD";
        case 2:
          return "AMF";
        case 3:
          return "SCOTCH";
        case 4:
          return "PORD";
        case 5:
          return "METIS";
        case 6:
          return "QAMD";
        default:
          return "ICNTL(7) = " +
                 std::to_string(mumps->id.infog[mumps_index(7)]);
      }
  }
} // namespace rodnet
