#include <families/bending_family.templates.h>
#include <families/hinge_family.h>

namespace rodnet
{
  template class BendingFamily<HingeStencils>;
} // namespace rodnet
