#include <core/model.h>

namespace rodnet
{
  double
  length_scale(const RodNetwork &network)
  {
    Vector3 low = network.vertex(0), high = low;
    for (unsigned int v = 0; v < network.n_vertices(); ++v)
      {
        low  = low.cwiseMin(network.vertex(v));
        high = high.cwiseMax(network.vertex(v));
      }
    return (high - low).norm();
  }
} // namespace rodnet
