// Built with clang only: deal.II 9.4 of Debian is compiled by gcc, which
// mangles the std::enable_if return type of
// TrilinosWrappers::SparseMatrix::vmult<MPI::Vector> differently from
// clang ("sr St7is_same" against "sr 3std7is_same ... E"), so a clang build
// of librodnet.so asks for a symbol that libdeal.ii.so does not define.
// This defines clang's symbol as a call of gcc's: the same function.
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace
{
  using Matrix = dealii::TrilinosWrappers::SparseMatrix;
  using Vector = dealii::TrilinosWrappers::MPI::Vector;
} // namespace

// A non-virtual member function takes `this` as its first argument.
void
gcc_vmult(const Matrix *, Vector &, const Vector &) __asm__(
  "_ZNK6dealii16TrilinosWrappers12SparseMatrix5vmultINS0_3MPI6VectorEEENSt9"
  "enable_ifIXsrSt7is_sameINT_10value_typeEdE5valueEvE4typeERS7_RKS7_");

void
clang_vmult(const Matrix *matrix, Vector &dst, const Vector &src) __asm__(
  "_ZNK6dealii16TrilinosWrappers12SparseMatrix5vmultINS0_3MPI6VectorEEENSt9"
  "enable_ifIXsr3std7is_sameINT_10value_typeEdEE5valueEvE4typeERS6_RKS6_");

void
clang_vmult(const Matrix *matrix, Vector &dst, const Vector &src)
{
  gcc_vmult(matrix, dst, src);
}
