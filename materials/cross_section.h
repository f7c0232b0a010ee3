#ifndef RODNET_MATERIALS_CROSS_SECTION_H
#define RODNET_MATERIALS_CROSS_SECTION_H

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace rodnet
{
  /**
   * Geometric constants of a rod's cross-section in the frame of the
   * material directors (d1, d2), with y1 and y2 the coordinates along d1 and
   * d2 measured from the centroid.
   *
   * The second moments follow the strains of the hinge kernels: kappa_1 is
   * the bending curvature about d1, so its stiffness involves the distance
   * from the d1 axis, I1 = int y2^2 dA; likewise I2 = int y1^2 dA
   * (Lestringant & Kochmann eq. 13, Korner et al. eq. 4.1).
   */
  struct CrossSection
  {
    /// Area A (m^2).
    double area;
    /// Second moment about d1, I1 = int y2^2 dA (m^4).
    double I1;
    /// Second moment about d2, I2 = int y1^2 dA (m^4).
    double I2;
    /// Torsion constant J (m^4): torque = G J times twist rate.
    double J;
  };

  /**
   * Solid circle of radius @p radius: A = pi r^2, I1 = I2 = pi r^4 / 4,
   * J = pi r^4 / 2 (polar moment, exact for a circle). Throws for a
   * radius that is not positive and finite.
   */
  CrossSection
  circle_section(double radius);

  /**
   * Solid rectangle with @p width along d1 and @p height along d2, so that
   * I1 = width height^3 / 12 (bending about d1) and
   * I2 = height width^3 / 12 (bending about d2). With a = max(width, height)
   * and b = min(width, height), the torsion constant is Saint-Venant's
   * series
   *   J = a b^3 / 3 [1 - 192 b / (pi^5 a) sum_{n odd} tanh(n pi a / (2 b))
   *       / n^5]
   * (Timoshenko & Goodier, Theory of Elasticity, torsion of rectangular
   * bars), which gives
   * 0.1406 a^4 for a square and tends to a b^3 / 3 for a thin strip.
   * Throws for dimensions that are not positive and finite.
   */
  CrossSection
  rectangle_section(double width, double height);

  /**
   * A section given by its constants, for shapes without a factory (tubes,
   * I-beams, measured values). Throws for values that are not positive and
   * finite.
   */
  CrossSection
  explicit_section(double area, double I1, double I2, double J);

  /**
   * The cross-section entries of a scene's material subsection: a selector
   * "Cross section" (circle | rectangle | explicit) and the dimensions each
   * choice reads ("Radius"; "Width", "Height"; "Area", "I1", "I2", "J").
   * Dimensions default to 0, which is rejected: a section must be given.
   */
  struct CrossSectionParameters
  {
    /// Declares the entries in the current subsection of @p prm.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Builds the section chosen in the current subsection of @p prm;
    /// throws with the name and value of an inadmissible entry.
    static CrossSection
    parse_parameters(const dealii::ParameterHandler &prm);
  };

  namespace internal
  {
    /**
     * The message "<context>: entry "<entry>" <requirement>, got <value>",
     * shared by the material classes so that every rejected input names its
     * entry the same way.
     */
    std::string
    entry_message(const std::string &context,
                  const std::string &entry,
                  const std::string &requirement,
                  double             value);

    /// Throws dealii::ExcMessage(entry_message(...)) unless @p value is
    /// positive and at most max_input_magnitude (so finite).
    void
    check_positive_entry(const std::string &context,
                         const std::string &entry,
                         double             value);

    /// Throws dealii::ExcMessage naming the entries @p inputs unless the
    /// value @p name = @p value they gave is finite and at most
    /// max_input_magnitude in magnitude: a product of admissible entries
    /// may still overflow.
    void
    check_derived_value(const std::string &context,
                        const std::string &inputs,
                        const std::string &name,
                        double             value);
  } // namespace internal
} // namespace rodnet

#endif
