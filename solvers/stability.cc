
#include <solvers/stability.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The tangent restricted to the free DoFs as a dense matrix, and the
    /// map from free to global indices.
    std::pair<Eigen::MatrixXd, std::vector<unsigned int>>
    free_block(const dealii::TrilinosWrappers::SparseMatrix &tangent,
               const dealii::AffineConstraints<double>      &constraints)
    {
      const unsigned int        n_dofs = tangent.m();
      std::vector<int>          free_index(n_dofs, -1);
      std::vector<unsigned int> global;
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (!constraints.is_constrained(i))
          {
            free_index[i] = global.size();
            global.push_back(i);
          }
      if (global.size() > max_dense_eigenvalue_dofs)
        throw std::invalid_argument(
          "the eigenvalue analysis is dense and limited to " +
          std::to_string(max_dense_eigenvalue_dofs) +
          " free DoFs; this model has " + std::to_string(global.size()) +
          ": use fewer segments or switch the eigenvalue probe off");
      Eigen::MatrixXd dense =
        Eigen::MatrixXd::Zero(global.size(), global.size());
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (free_index[i] >= 0)
          for (auto entry = tangent.begin(i); entry != tangent.end(i); ++entry)
            if (free_index[entry->column()] >= 0)
              dense(free_index[i], free_index[entry->column()]) =
                entry->value();
      return {dense, global};
    }
  } // namespace

  std::vector<double>
  lowest_eigenvalues(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                     const dealii::AffineConstraints<double>      &constraints,
                     const unsigned int                            n)
  {
    const auto [dense, global] = free_block(tangent, constraints);
    if (global.empty())
      return {};
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      dense,
      Eigen::EigenvaluesOnly);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("the dense eigenvalue solver did not converge");
    const Eigen::VectorXd &all = solver.eigenvalues(); // increasing order
    return std::vector<double>(all.data(),
                               all.data() +
                                 std::min<std::size_t>(n, global.size()));
  }

  std::pair<double, std::vector<double>>
  lowest_eigenpair(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                   const dealii::AffineConstraints<double>      &constraints)
  {
    const auto [dense, global] = free_block(tangent, constraints);
    if (global.empty())
      throw std::invalid_argument("every DoF is constrained: no eigenpair");
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("the dense eigenvalue solver did not converge");
    std::vector<double> vector(tangent.m(), 0.0);
    for (unsigned int k = 0; k < global.size(); ++k)
      vector[global[k]] = solver.eigenvectors()(k, 0);
    return {solver.eigenvalues()[0], vector};
  }
} // namespace rodnet
