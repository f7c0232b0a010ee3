#include <families/bending_family.templates.h>
#include <families/junction_family.h>

namespace rodnet
{
  template class BendingFamily<JunctionStencils>;
} // namespace rodnet
