
#include <solvers/stability.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <stdexcept>

namespace rodnet
{
  std::vector<double>
  lowest_eigenvalues(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                     const dealii::AffineConstraints<double>      &constraints,
                     const unsigned int                            n)
  {
    const unsigned int   n_dofs = tangent.m();
    std::vector<int>     free_index(n_dofs, -1);
    unsigned int         n_free = 0;
    for (unsigned int i = 0; i < n_dofs; ++i)
      if (!constraints.is_constrained(i))
        free_index[i] = n_free++;
    if (n_free > max_dense_eigenvalue_dofs)
      throw std::invalid_argument(
        "the eigenvalue analysis is dense and limited to " +
        std::to_string(max_dense_eigenvalue_dofs) + " free DoFs; this model "
        "has " + std::to_string(n_free) + ": use fewer segments or switch "
        "the eigenvalue probe off");
    if (n_free == 0)
      return {};

    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n_free, n_free);
    for (unsigned int i = 0; i < n_dofs; ++i)
      if (free_index[i] >= 0)
        for (auto entry = tangent.begin(i); entry != tangent.end(i); ++entry)
          if (free_index[entry->column()] >= 0)
            dense(free_index[i], free_index[entry->column()]) = entry->value();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      dense, Eigen::EigenvaluesOnly);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("the dense eigenvalue solver did not converge");
    const Eigen::VectorXd &all = solver.eigenvalues(); // increasing order
    return std::vector<double>(all.data(),
                               all.data() + std::min<unsigned int>(n, n_free));
  }
} // namespace rodnet
