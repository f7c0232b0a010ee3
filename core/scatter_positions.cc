#include <deal.II/base/parallel.h>

#include <core/scatter_positions.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace
  {
    /// Four independent multiply-xor lanes (a serial hash would wait on
    /// each multiply): the fingerprint is taken at every assembly.
    class Fingerprint
    {
    public:
      void
      add(const int *data, const std::size_t n)
      {
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4)
          for (unsigned int l = 0; l < 4; ++l)
            lanes[l] =
              (lanes[l] ^ static_cast<std::uint32_t>(data[i + l])) * prime;
        for (; i < n; ++i)
          lanes[0] = (lanes[0] ^ static_cast<std::uint32_t>(data[i])) * prime;
      }

      void
      add(const std::uint64_t value)
      {
        lanes[1] = (lanes[1] ^ value) * prime;
      }

      std::uint64_t
      value() const
      {
        return ((lanes[0] * prime ^ lanes[1]) * prime ^ lanes[2]) * prime ^
               lanes[3];
      }

    private:
      static constexpr std::uint64_t prime    = 0x100000001b3ULL;
      std::uint64_t                  lanes[4] = {0xcbf29ce484222325ULL,
                                                 0x84222325cbf29ce4ULL,
                                                 0x9ce484222325cbf2ULL,
                                                 0x2325cbf29ce48422ULL};
    };
  } // namespace


  std::uint64_t
  ScatterPositions::fingerprint(const CsrArrays         &csr,
                                const std::vector<bool> *fixed)
  {
    Fingerprint hash;
    hash.add(static_cast<std::uint64_t>(csr.n_rows));
    hash.add(static_cast<std::uint64_t>(csr.first_row));
    hash.add(csr.offsets, csr.n_rows + 1);

    // The columns (the bulk: 8 million for a rod of 1e5 vertices) in
    // pieces of a fixed size, one hash each, then the hashes in order.
    constexpr std::size_t      piece    = std::size_t(1) << 16;
    const std::size_t          n        = csr.offsets[csr.n_rows];
    const std::size_t          n_pieces = (n + piece - 1) / piece;
    std::vector<std::uint64_t> pieces(n_pieces);
    dealii::parallel::apply_to_subranges(
      std::size_t(0),
      n_pieces,
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t p = begin; p < end; ++p)
          {
            Fingerprint piece_hash;
            piece_hash.add(csr.columns + p * piece,
                           std::min(piece, n - p * piece));
            pieces[p] = piece_hash.value();
          }
      },
      4);
    for (const std::uint64_t value : pieces)
      hash.add(value);
    hash.add(fixed == nullptr ? 0 : 1);
    if (fixed != nullptr)
      for (std::size_t i = 0; i < fixed->size(); i += 64)
        {
          std::uint64_t word = 0;
          for (std::size_t b = 0; b < 64 && i + b < fixed->size(); ++b)
            word |= static_cast<std::uint64_t>((*fixed)[i + b]) << b;
          hash.add(word);
        }
    return hash.value();
  }


  ScatterPositions::ScatterPositions(
    const std::vector<std::unique_ptr<ElementFamily>> &families,
    const CsrArrays                                   &csr,
    const std::vector<bool>                           *fixed,
    const std::uint64_t                                fingerprint)
      : pattern_fingerprint(fingerprint)
  {
    for (const auto &family : families)
      this->families.push_back(find(*family, csr, fixed));
    diagonal_places.resize(csr.n_rows, -1);
    for (int row = 0; row < csr.n_rows; ++row)
      {
        const int *begin = csr.columns + csr.offsets[row];
        const int *end   = csr.columns + csr.offsets[row + 1];
        const int *at =
          std::find(begin, end, csr.column_of(csr.first_row + row));
        if (at != end)
          diagonal_places[row] = at - csr.columns;
      }
  }


  ScatterPositions::Family
  ScatterPositions::find(const ElementFamily     &family,
                         const CsrArrays         &csr,
                         const std::vector<bool> *fixed)
  {
    const auto is_fixed = [&](const global_dof_index dof) {
      return fixed != nullptr && (*fixed)[dof];
    };
    Family                        result;
    std::vector<global_dof_index> dofs;
    result.starts.reserve(family.n_stencils() + 1);
    result.starts.push_back(0);
    for (unsigned int s = 0; s < family.n_stencils(); ++s)
      {
        family.get_dofs(s, dofs);
        // A stencil without a row of this process is not evaluated here.
        if (std::none_of(dofs.begin(), dofs.end(), [&](const auto d) {
              return csr.row_of(d) >= 0;
            }))
          {
            result.starts.push_back(result.entries.size());
            continue;
          }
        for (const global_dof_index row : dofs)
          {
            const int  local_row = csr.row_of(row);
            const int *begin =
              csr.columns + csr.offsets[std::max(local_row, 0)];
            const int *end =
              csr.columns + csr.offsets[std::max(local_row, 0) + 1];
            for (const global_dof_index column : dofs)
              {
                // Rows of other processes are theirs to add.
                if (local_row < 0 || is_fixed(row) || is_fixed(column))
                  {
                    result.entries.push_back(skip());
                    continue;
                  }
                const int *at = std::find(begin, end, csr.column_of(column));
                if (at == end)
                  throw std::logic_error(
                    "ScatterPositions: family \"" + family.name() +
                    "\", stencil " + std::to_string(s) + " couples DoFs " +
                    std::to_string(row) + " and " + std::to_string(column) +
                    ", which the matrix's sparsity pattern does not hold");
                if (at - begin >= skip())
                  return Family();
                result.entries.push_back(std::uint8_t(at - begin));
              }
          }
        result.starts.push_back(result.entries.size());
      }
    result.entries.shrink_to_fit();
    return result;
  }


  std::shared_ptr<const ScatterPositions>
  ScatterPositionsCache::get(
    const std::vector<std::unique_ptr<ElementFamily>> &families,
    const CsrArrays                                   &csr,
    const std::vector<bool>                           *fixed)
  {
    const std::uint64_t         key = ScatterPositions::fingerprint(csr, fixed);
    std::lock_guard<std::mutex> lock(mutex);
    if (positions == nullptr || positions->pattern() != key)
      positions =
        std::make_shared<const ScatterPositions>(families, csr, fixed, key);
    return positions;
  }
} // namespace rodnet
