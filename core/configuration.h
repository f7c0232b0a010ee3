#ifndef RODNET_CORE_CONFIGURATION_H
#define RODNET_CORE_CONFIGURATION_H

#include <deal.II/lac/trilinos_vector.h>

#include <core/activation_field.h>
#include <core/dof_layout.h>
#include <core/dof_values.h>
#include <core/rod_network.h>
#include <elements/hinge_kernel.h>
#include <elements/junction_kernel.h>

#include <vector>

namespace rodnet
{
  /**
   * Undeformed and reference data of a rod network (Korner et al. 2021,
   * section 2c): undeformed segment lengths, and per segment the reference
   * director frame D^j with the value of its twist DoF at the reference, per
   * hinge the reference twist of the kernels that track it. The current
   * configuration is the DoF vector (vertex displacements, twist angles).
   * The reference is reset to the current configuration after every
   * converged step, so that no tangent turns by 180 degrees within a step.
   *
   * Junctions (Lestringant & Kochmann section 2.2): per junction element
   * the reference frame of its ghost segment, initially the frame of the
   * physical segment it continues (so the undeformed network is stress
   * free), and per junction the rotation accumulated over the converged
   * steps; the quaternion DoFs hold the increment since the reference.
   *
   * Natural strains (doc/theory.md, "Natural shape"): per hinge the strains
   * kappa_bar at which it is stress free, the hinge's own measures in the
   * undeformed configuration for rods of NaturalShape::initial_geometry,
   * zero for NaturalShape::straight. They are fixed at construction: the
   * measures depend on positions and material frames only, not on the
   * reference, so reset_reference() leaves them valid. Activation fields
   * (add_activation()) add to them, to the junction elements' (zero
   * otherwise) and to the segments' axial eigenstrain, the ramped ones
   * times the activation factor (follow_activation()), the others times
   * their functions of time (set_activation_time()).
   */
  class Configuration
  {
  public:
    /**
     * Undeformed lengths and frames: d3 along each segment, d1 the rod's
     * director hint made orthogonal to it. Throws, naming rod and segment,
     * where the hint is parallel to a segment.
     */
    Configuration(
      const RodNetwork                          &network,
      const DofLayout                           &layout,
      const std::vector<const HingeKernel *>    &rod_kernels,
      const std::vector<const JunctionKernel *> &rod_junction_kernels);

    /// Current position of vertex @p v for the DoF vector @p u.
    Vector3
    position(const DofValues &u, unsigned int v) const;

    /// Local DoF vector of a hinge as its kernel expects it.
    HingeVector
    hinge_dofs(const DofValues &u, const HingeStencil &hinge) const;

    /// Local DoF vector of a segment, (x_j, x_{j+1}).
    SegmentVector
    segment_dofs(const DofValues &u, const SegmentStencil &segment) const;

    /// Local DoF vector of a junction element, (x_a, x_b, phi, q).
    HingeVector
    junction_dofs(const DofValues &u, const JunctionStencil &junction) const;

    /// junction_dofs() with the quaternion q = (1, 0, 0, 0) of the
    /// reference, whatever @p u holds (or before the junction family has
    /// declared the quaternions' DoFs).
    HingeVector
    junction_dofs_at_reference_rotation(const DofValues       &u,
                                        const JunctionStencil &junction) const;

    /// Reference data of junction element number @p e.
    const JunctionReference &
    junction_reference(unsigned int e) const
    {
      return junction_refs[e];
    }

    /**
     * Undeformed Voronoi length of junction element @p e: half its physical
     * segment, the part of the rod between the junction and the segment's
     * midpoint (the paper takes the whole segment; see doc/junctions.md).
     */
    double
    junction_voronoi_length(unsigned int e) const
    {
      return junction_lengths[e];
    }

    /// Incremental rotation of junction @p j since the reference, a unit
    /// quaternion.
    Quaternion
    junction_increment(const dealii::TrilinosWrappers::MPI::Vector &u,
                       unsigned int                                 j) const;

    /// Rotation of junction @p j from the undeformed configuration.
    Quaternion
    junction_rotation(const dealii::TrilinosWrappers::MPI::Vector &u,
                      unsigned int                                 j) const
    {
      return (junction_increment(u, j) * accumulated_rotations[j]).normalized();
    }

    /// Rotation of junction @p j at the reference configuration.
    const Quaternion &
    reference_rotation(unsigned int j) const
    {
      return accumulated_rotations[j];
    }

    /// Reference data of hinge number @p h.
    const HingeReference &
    hinge_reference(unsigned int h) const
    {
      return hinge_refs[h];
    }

    /**
     * Natural strains of hinge number @p h (integrated, as the kernel's
     * strains): the material sees kappa - natural_strains(h).
     */
    const Vector3 &
    natural_strains(unsigned int h) const
    {
      return hinge_natural_strains[h];
    }

    /// Natural strains of junction element @p e (integrated over its
    /// Voronoi length): zero but for activation fields.
    Vector3
    junction_natural_strains(unsigned int e) const
    {
      return activation.empty() ? Vector3::Zero() : activation.junction_now[e];
    }

    /// Axial eigenstrain of the segment on cell @p cell from activation
    /// fields (the material's own comes on top): the segment's material
    /// sees its strain less this.
    double
    segment_eigenstrain(unsigned int cell) const
    {
      return activation.empty() ? 0. : activation.segment_now[cell];
    }

    /**
     * Adds the activation field @p field to rod @p rod (doc/morphing.md):
     * each hinge's natural strains gain the integral of (kappa_1, kappa_2,
     * tau) over its Voronoi cell, each junction element's over its half
     * segment, each segment's eigenstrain the mean over the segment. So a
     * field uniform over a rod gives what a material's natural shape gives,
     * and a field's total turn and stretch are kept exactly, wherever its
     * region ends. @p drive: held fixed, scaled by the activation factor
     * or by its own function of time (set_activation_time()).
     */
    void
    add_activation(unsigned int           rod,
                   const ActivationField &field,
                   const ActivationDrive &drive);

    /// Puts the ramped activation fields at @p factor (the load factor);
    /// nothing without activation fields or if they are at it.
    void
    follow_activation(double factor);

    /// Puts the fields driven by functions of time at time @p time (their
    /// functions throw where they have no finite value).
    void
    set_activation_time(double time);

    /// The factors of the fields driven by functions of time, one per
    /// function, at the last set_activation_time() (empty if none).
    std::vector<double>
    activation_time_factors() const;

    /// Whether an activation field is driven by @p kind (the load factor,
    /// a function of time).
    bool
    has_activation_driven_by(ActivationDrive::Kind kind) const;

    /**
     * The densities (kappa_1, kappa_2, twist rate, axial eigenstrain) the
     * activation fields give each segment (its active cell), their mean
     * over it, at the factors of the last follow_activation() and
     * set_activation_time(): empty without activation fields.
     */
    std::vector<Eigen::Vector4d>
    segment_activation() const;

    /// Current director frame of the segment on cell @p cell.
    Quaternion
    director_frame(const dealii::TrilinosWrappers::MPI::Vector &u,
                   unsigned int                                 cell) const;

    /// Current length of the segment on active cell @p cell.
    double
    segment_length(const DofValues &u, unsigned int cell) const;

    double
    rest_length(unsigned int cell) const
    {
      return rest_lengths[cell];
    }

    /// Undeformed Voronoi length of hinge @p h (mean of its segments).
    double
    voronoi_length(unsigned int h) const
    {
      return voronoi_lengths[h];
    }

    /// Makes the configuration @p u the new reference (Korner et al. 2c).
    void
    reset_reference(const dealii::TrilinosWrappers::MPI::Vector &u);

    /// Whether hinge @p h closes its rod: a closed rod's hinge that joins
    /// its last segment to its first.
    bool
    closes(const HingeStencil &h) const;

    /// Whether hinge @p h closes a closed rod whose frame makes an odd
    /// number of half turns (Rod::frame_half_turns): its strains are
    /// measured against the first segment's frame turned by pi about the
    /// tangent.
    bool
    closes_with_a_flip(const HingeStencil &h) const;

  private:
    /// What the activation fields of one drive add: per hinge and junction
    /// element their integrated strains, per cell (segment) the mean
    /// densities, the last one its eigenstrain.
    struct ActivationShare
    {
      ActivationDrive              drive;
      std::vector<Vector3>         hinge, junction;
      std::vector<Eigen::Vector4d> cell;
      /// Its factor at the last follow_activation() and
      /// set_activation_time().
      double factor = 0.;
    };

    /// The shares of the activation fields, one per drive, and their sum
    /// at the factors (add_activation()).
    struct Activation
    {
      bool
      empty() const
      {
        return segment_now.empty();
      }
      std::vector<ActivationShare> shares;
      std::vector<Vector3>         junction_now;
      std::vector<double>          segment_now;
      /// The natural strains of the geometry alone, per hinge.
      std::vector<Vector3> hinge_geometric;
      /// Per rod, its hinges and its junction elements; per cell, its
      /// segment's place in its rod.
      std::vector<std::vector<unsigned int>> rod_hinges, rod_junctions;
      std::vector<unsigned int>              cell_position;
      /// The load factor of the sums; NaN: to be summed again.
      double factor = 0.;
    };

    /// The share of @p drive, made if new.
    ActivationShare &
    activation_share(const ActivationDrive &drive);

    /// Sums the shares at their factors into the natural strains.
    void
    sum_activation();

    /// Sizes the activation storage (first add_activation()).
    void
    start_activation();

    /// The undeformed arc length of rod @p rod's vertices, from its first.
    std::vector<double>
    vertex_arc_lengths(unsigned int rod) const;

    /// The reference frames of hinge @p i from the segments' frames.
    void
    set_hinge_frames(unsigned int i);

    /// The constructor's parts: the hinges' kernels, Voronoi lengths and
    /// frames; the junction elements' kernels, lengths and frames; then
    /// the reference twists and natural strains at the undeformed state.
    void
    add_hinge_references(const std::vector<const HingeKernel *> &rod_kernels);
    void
    add_junction_references(
      const std::vector<const JunctionKernel *> &rod_junction_kernels);
    void
    set_reference_twists_and_natural_strains();

    const RodNetwork                   *network;
    const DofLayout                    *layout;
    std::vector<const HingeKernel *>    kernels; ///< per hinge
    std::vector<double>                 rest_lengths;
    std::vector<double>                 voronoi_lengths;
    std::vector<Quaternion>             frames; ///< D^j per cell
    std::vector<double>                 twist_at_reference;
    std::vector<HingeReference>         hinge_refs;
    std::vector<Vector3>                hinge_natural_strains;
    Activation                          activation;
    std::vector<const JunctionKernel *> junction_kernels; ///< per element
    std::vector<JunctionReference>      junction_refs;
    std::vector<double>                 junction_lengths;
    std::vector<Quaternion>             accumulated_rotations; ///< per junction
    std::vector<Vector3>                undeformed;            ///< per vertex
    std::vector<unsigned int>           segment_index;         ///< per cell
    /// Per hinge: whether it closes a Möbius band (closes_with_a_flip()).
    std::vector<bool> closure_flips;
  };
} // namespace rodnet

#endif
