#ifndef RODNET_MATERIALS_ROD_STIFFNESS_H
#define RODNET_MATERIALS_ROD_STIFFNESS_H

namespace rodnet
{
  /// Rigidities of a rod: axial EA (N), bending EI1 about d1 and EI2 about
  /// d2 (N m^2), torsional GJ (N m^2).
  struct RodStiffness
  {
    double EA;
    double EI1;
    double EI2;
    double GJ;
  };
} // namespace rodnet

#endif
