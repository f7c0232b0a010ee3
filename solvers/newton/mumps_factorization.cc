#include <deal.II/base/mpi.h>

#include <solvers/newton/epetra_entries.h>
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
      id.icntl[mumps_index(4)]  = 0;
      id.icntl[mumps_index(5)]  = 0; // assembled matrix
      id.icntl[mumps_index(18)] = 0; // centralized on the host
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
  } // namespace


  MumpsFactorization::MumpsFactorization(const MatrixType &matrix)
      : mumps(std::make_unique<Instance>())
      , matrix(matrix)
  {
    const MPI_Comm communicator = matrix.get_mpi_communicator();
    if (dealii::Utilities::MPI::n_mpi_processes(communicator) != 1)
      throw std::invalid_argument(
        "MUMPS (Linear solver = mumps) runs on one process for now");
    for_each_entry(matrix.trilinos_matrix(),
                   [&](const int row, const int column, double) {
                     if (column <= row)
                       {
                         rows.push_back(row + 1);
                         columns.push_back(column + 1);
                       }
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
    id.n   = matrix.trilinos_matrix().NumMyRows();
    id.nnz = rows.size();
    id.irn = rows.data();
    id.jcn = columns.data();
    id.a   = values.data();
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


  void
  MumpsFactorization::factorize()
  {
    std::size_t k = 0;
    for_each_entry(matrix.trilinos_matrix(),
                   [&](const int row, const int column, const double value) {
                     if (column <= row && k < values.size())
                       values[k] = value;
                     k += column <= row;
                   });
    if (k != values.size())
      throw std::logic_error(
        "the tangent's pattern changed after MUMPS's analysis of it");
    factorized         = false;
    DMUMPS_STRUC_C &id = mumps->id;
    id.job             = 2;
    dmumps_c(&id);
    const int status = id.infog[mumps_index(1)];
    if (status == -8 || status == -9)
      {
        // MUMPS's estimate of its work space fell short (delayed pivots
        // grow the fronts): once more with twice the relaxation.
        id.icntl[mumps_index(14)] *= 2;
        run(2, "factorization");
      }
    else if (status < 0)
      throw std::runtime_error("MUMPS's factorization failed: " +
                               mumps_error(status, id.infog[mumps_index(2)]));
    factorized = true;
  }


  void
  MumpsFactorization::solve_columns(const int n_columns)
  {
    DMUMPS_STRUC_C &id = mumps->id;
    id.nrhs            = n_columns;
    id.lrhs            = id.n;
    id.rhs             = rhs.data();
    run(3, "solve");
  }


  void
  MumpsFactorization::solve(const VectorType &b, VectorType &x)
  {
    const double *in = b.trilinos_vector()[0];
    rhs.assign(in, in + mumps->id.n);
    solve_columns(1);
    x = b;
    std::copy(rhs.begin(), rhs.end(), x.trilinos_vector()[0]);
  }


  void
  MumpsFactorization::solve(const VectorType &b,
                            VectorType       &x,
                            const VectorType &c,
                            VectorType       &y)
  {
    const int     n    = mumps->id.n;
    const double *in_b = b.trilinos_vector()[0];
    const double *in_c = c.trilinos_vector()[0];
    rhs.resize(2 * std::size_t(n));
    std::copy(in_b, in_b + n, rhs.begin());
    std::copy(in_c, in_c + n, rhs.begin() + n);
    solve_columns(2);
    x = b;
    y = c;
    std::copy(rhs.begin(), rhs.begin() + n, x.trilinos_vector()[0]);
    std::copy(rhs.begin() + n, rhs.end(), y.trilinos_vector()[0]);
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


  unsigned int
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
