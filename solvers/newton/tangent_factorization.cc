#include <deal.II/base/mpi.h>
#include <deal.II/base/patterns.h>

#include <base/phase_times.h>
#include <core/scatter_positions.h>
#include <solvers/newton/band_lu.h>
#include <solvers/newton/epetra_entries.h>
#include <solvers/newton/klu_factorization.h>
#include <solvers/newton/mumps_factorization.h>
#include <solvers/newton/phase_timed_factorization.h>
#include <solvers/newton/tangent_factorization.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace rodnet
{
  namespace
  {
    using VectorType = TangentFactorization::VectorType;
    using MatrixType = TangentFactorization::MatrixType;

    /// The lower and upper half-widths of the band of @p m's pattern, its
    /// rows and columns renumbered by @p new_index (none: as they are).
    std::pair<int, int>
    band_widths(const Epetra_CrsMatrix &m, const std::vector<int> &new_index)
    {
      int lower = 0, upper = 0;
      for_each_entry(m, [&](int row, int column, double) {
        if (!new_index.empty())
          {
            row    = new_index[row];
            column = new_index[column];
          }
        lower = std::max(lower, row - column);
        upper = std::max(upper, column - row);
      });
      return {lower, upper};
    }

    /**
     * The reverse Cuthill-McKee numbering of @p m's (symmetrized) pattern
     * (George & Liu 1981, ch. 4): each connected part breadth first from a
     * row of least degree, the neighbours of a row by increasing degree, the
     * whole order reversed; new_index[old row]. It brings the multipliers
     * of inextensible rods, numbered after all other DoFs, next to their
     * segments, so that a rod's tangent is a narrow band again.
     */
    std::vector<int>
    reverse_cuthill_mckee(const Epetra_CrsMatrix &m)
    {
      const int                     n = m.NumMyRows();
      std::vector<std::vector<int>> adjacent(n);
      for_each_entry(m, [&](const int row, const int column, double) {
        if (row != column)
          {
            adjacent[row].push_back(column);
            adjacent[column].push_back(row);
          }
      });
      for (std::vector<int> &a : adjacent)
        {
          std::sort(a.begin(), a.end());
          a.erase(std::unique(a.begin(), a.end()), a.end());
        }
      const auto by_degree = [&](const int a, const int b) {
        return adjacent[a].size() < adjacent[b].size();
      };
      std::vector<int> starts(n);
      std::iota(starts.begin(), starts.end(), 0);
      std::stable_sort(starts.begin(), starts.end(), by_degree);
      std::vector<int>  order;
      std::vector<bool> placed(n, false);
      std::vector<int>  next;
      for (const int start : starts)
        {
          if (placed[start])
            continue;
          placed[start] = true;
          order.push_back(start);
          for (std::size_t head = order.size() - 1; head < order.size(); ++head)
            {
              next.clear();
              for (const int j : adjacent[order[head]])
                if (!placed[j])
                  {
                    placed[j] = true;
                    next.push_back(j);
                  }
              std::stable_sort(next.begin(), next.end(), by_degree);
              order.insert(order.end(), next.begin(), next.end());
            }
        }
      std::vector<int> new_index(n);
      for (int k = 0; k < n; ++k)
        new_index[order[n - 1 - k]] = k;
      return new_index;
    }


    /**
     * The band LU with partial pivoting of BandLU, on the tangent's rows
     * and columns as they are or renumbered to narrow the band.
     */
    class BandFactorization : public TangentFactorization
    {
    public:
      /// The band of @p matrix with its rows and columns renumbered by
      /// @p new_index (empty: as they are), of half-widths @p kl_ku there.
      BandFactorization(const MatrixType         &matrix,
                        const std::pair<int, int> kl_ku,
                        std::vector<int>          new_index = {})
          : matrix(matrix.trilinos_matrix())
          , n(this->matrix.NumMyRows())
          , lu(n, kl_ku.first, kl_ku.second)
          , new_index(std::move(new_index))
      {
        // Each stored entry's place in the band, in the order of the
        // compressed rows: a factorization then copies the values without
        // asking the matrix for its rows and their global columns.
        for_each_entry(this->matrix,
                       [&](const int row, const int column, double) {
                         places.push_back(place(row, column));
                       });
      }

      void
      factorize() override
      {
        lu.clear();
        std::vector<double> &band    = lu.storage();
        int                 *offsets = nullptr, *columns = nullptr;
        double              *values = nullptr;
        matrix.ExtractCrsDataPointers(offsets, columns, values);
        if (values != nullptr && std::size_t(offsets[n]) == places.size())
          for (std::size_t k = 0; k < places.size(); ++k)
            band[places[k]] = values[k];
        else // storage not optimized: row by row
          for_each_entry(matrix,
                         [&](const int    row,
                             const int    column,
                             const double value) {
                           band[place(row, column)] = value;
                         });
        if (const int column = lu.factorize(); column != 0)
          throw SingularTangent(
            "the tangent is singular (band LU: zero pivot in column " +
            std::to_string(column) + ")");
      }

      using TangentFactorization::solve;

      void
      solve(const VectorType &b, VectorType &x) override
      {
        x            = b;
        double *data = x.trilinos_vector()[0];
        if (new_index.empty())
          {
            lu.solve(data);
            return;
          }
        renumbered.resize(n);
        for (int i = 0; i < n; ++i)
          renumbered[new_index[i]] = data[i];
        lu.solve(renumbered.data());
        for (int i = 0; i < n; ++i)
          data[i] = renumbered[new_index[i]];
      }

      std::string
      name() const override
      {
        return "band";
      }

      /// The band as stored, room for the row exchanges included.
      double
      factor_entries() const override
      {
        return lu.size();
      }

    private:
      /// Where entry (@p row, @p column) is in the band's storage.
      std::size_t
      place(int row, int column) const
      {
        if (!new_index.empty())
          {
            row    = new_index[row];
            column = new_index[column];
          }
        return lu.entry(row, column);
      }

      const Epetra_CrsMatrix  &matrix;
      const int                n;
      BandLU                   lu;
      std::vector<std::size_t> places;
      /// The band's numbering of the rows, empty where it is the matrix's.
      std::vector<int>    new_index;
      std::vector<double> renumbered;
    };
  } // namespace


  void
  TangentFactorization::check_kind(const std::string &kind)
  {
    if (!dealii::Patterns::Selection(kinds).match(kind))
      throw std::invalid_argument("unknown linear solver \"" + kind +
                                  "\"; known: " + kinds);
  }


  std::unique_ptr<TangentFactorization>
  TangentFactorization::create(const MatrixType  &matrix,
                               const std::string &kind)
  {
    check_kind(kind);
    const phase_times::Scope phase(phase_times::Phase::factorization_analysis);
    return phase_timed(make_factorization(matrix, kind));
  }


  std::unique_ptr<TangentFactorization>
  TangentFactorization::make_factorization(const MatrixType  &matrix,
                                           const std::string &kind)
  {
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator());
    if (n_processes > 1 && (kind == "klu" || kind == "band"))
      throw std::invalid_argument(
        std::string(kind == "klu" ? "KLU" : "the band LU") +
        " (Linear solver = " + kind +
        ") runs on one process, and the tangent is distributed over " +
        std::to_string(n_processes) +
        " processes; take Linear solver = mumps (or auto)");
    if (kind == "mumps" || n_processes > 1)
      return std::make_unique<MumpsFactorization>(matrix);
    if (kind == "klu")
      return make_klu_factorization(matrix);
    const Epetra_CrsMatrix &m      = matrix.trilinos_matrix();
    const auto              narrow = [](const std::pair<int, int> &widths) {
      return widths.first <= max_auto_band_width &&
             widths.second <= max_auto_band_width;
    };
    const std::pair<int, int> widths = band_widths(m, {});
    if (narrow(widths))
      return std::make_unique<BandFactorization>(matrix, widths);
    // Renumbered, the band may be narrow (a rod with multipliers).
    std::vector<int>          new_index         = reverse_cuthill_mckee(m);
    const std::pair<int, int> renumbered_widths = band_widths(m, new_index);
    if (narrow(renumbered_widths))
      return std::make_unique<BandFactorization>(matrix,
                                                 renumbered_widths,
                                                 std::move(new_index));
    if (kind == "band")
      return std::make_unique<BandFactorization>(matrix, widths);
    if (kind == "auto" && m.NumGlobalRows() >= min_auto_mumps_rows)
      return std::make_unique<MumpsFactorization>(matrix);
    return make_klu_factorization(matrix);
  }


  std::shared_ptr<TangentFactorization>
  TangentFactorizationCache::get(const MatrixType  &matrix,
                                 const std::string &kind)
  {
    const Epetra_CrsMatrix &m = matrix.trilinos_matrix();
    CsrArrays               csr;
    double                 *values = nullptr;
    m.ExtractCrsDataPointers(csr.offsets, csr.columns, values);
    csr.n_rows = m.NumMyRows();
    // Each process compares its own rows; all renew the factorization
    // together (MUMPS's analysis is collective) if any of them changed.
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator());
    const bool          readable = csr.offsets != nullptr;
    const std::uint64_t key =
      readable ? ScatterPositions::fingerprint(csr, nullptr) : 0;
    const bool renew =
      dealii::Utilities::MPI::logical_or(factorization == nullptr ||
                                           !readable || &m != this->matrix ||
                                           key != pattern ||
                                           !serves(kind, n_processes),
                                         matrix.get_mpi_communicator());
    if (renew)
      {
        factorization = TangentFactorization::create(matrix, kind);
        this->matrix  = &m;
        pattern       = key;
        this->kind    = kind;
      }
    return factorization;
  }


  bool
  TangentFactorizationCache::serves(const std::string &kind,
                                    const unsigned int n_processes) const
  {
    if (kind == this->kind)
      return true;
    // On several processes every kind that runs there is MUMPS.
    const bool kept_mumps = factorization->name() == "mumps";
    return kept_mumps &&
           (kind == "mumps" || (kind == "auto" && n_processes > 1));
  }
} // namespace rodnet
