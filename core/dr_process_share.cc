#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <core/dr_process_share.h>

namespace rodnet
{
  DrProcessShare::DrProcessShare(const MPI_Comm           communicator,
                                 const unsigned int       n_elements,
                                 const unsigned int       stencil_size,
                                 const Stencil           &stencil,
                                 const std::vector<bool> &fixed)
      : communicator(communicator)
      , n_processes(dealii::Utilities::MPI::n_mpi_processes(communicator))
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const auto boundary = [&](const unsigned int p) {
      return static_cast<unsigned int>(std::size_t(n_elements) * p /
                                       n_processes);
    };
    element_range = {boundary(rank), boundary(rank + 1)};

    // Per DoF: the lowest rank touching it (n_processes if none) and how
    // many processes touch it, from every process's elements.
    const std::size_t         n_dofs = fixed.size();
    std::vector<unsigned int> lowest(n_dofs, n_processes), touching(n_dofs, 0);
    for (unsigned int e = element_range.first; e < element_range.second; ++e)
      for (unsigned int k = 0; k < stencil_size; ++k)
        {
          lowest[stencil(e)[k]]   = rank;
          touching[stencil(e)[k]] = 1;
        }
    const std::vector<unsigned int> touched_here = touching;
    if (distributed())
      {
        dealii::Utilities::MPI::min(dealii::ArrayView<const unsigned int>(
                                      lowest),
                                    communicator,
                                    dealii::ArrayView<unsigned int>(lowest));
        dealii::Utilities::MPI::sum(dealii::ArrayView<const unsigned int>(
                                      touching),
                                    communicator,
                                    dealii::ArrayView<unsigned int>(touching));
      }

    owned.resize(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        owned[i] = lowest[i] == rank || (lowest[i] == n_processes && rank == 0);
        if (!fixed[i] && touched_here[i] == 1)
          touched_free.push_back(i);
        if (!fixed[i] && owned[i])
          owned_free.push_back(i);
        if (distributed() && (fixed[i] || touching[i] > 1))
          shared.push_back(i);
      }
  }


  double
  DrProcessShare::sum(const double value) const
  {
    return distributed() ? dealii::Utilities::MPI::sum(value, communicator) :
                           value;
  }


  void
  DrProcessShare::sum(std::vector<double> &values) const
  {
    if (distributed())
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(values),
                                  communicator,
                                  dealii::ArrayView<double>(values));
  }


  double
  DrProcessShare::max(const double value) const
  {
    return distributed() ? dealii::Utilities::MPI::max(value, communicator) :
                           value;
  }


  void
  DrProcessShare::add_shared(dealii::Vector<double> &v) const
  {
    if (!distributed())
      return;
    std::vector<double> entries(shared.size());
    for (std::size_t k = 0; k < shared.size(); ++k)
      entries[k] = v[shared[k]];
    sum(entries);
    for (std::size_t k = 0; k < shared.size(); ++k)
      v[shared[k]] = entries[k];
  }


  void
  DrProcessShare::complete(dealii::Vector<double> &v) const
  {
    if (!distributed())
      return;
    for (unsigned int i = 0; i < v.size(); ++i)
      if (!owned[i])
        v[i] = 0;
    const dealii::ArrayView<double> entries(v.begin(), v.size());
    dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(entries),
                                communicator,
                                entries);
  }
} // namespace rodnet
