#include <deal.II/base/utilities.h>

#include <geometry/rod_generators.h>
#include <io/gmsh_rods.h>
#include <io/rod_generator_entries.h>
#include <io/scene_entries.h>

#include <cmath>
#include <stdexcept>
#include <tuple>

namespace rodnet
{
  namespace
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using scene_entries::get_vector;
    using scene_entries::vector_pattern;

    constexpr double degree = M_PI / 180;

    /// A generator of one open rod of "Segments" segments.
    class OpenRodGenerator : public GeometryGenerator
    {
    public:
      std::optional<ProblemSize>
      planned_size(const dealii::ParameterHandler &,
                   const GeneratorInput &input) const override
      {
        return rods_size(1, input.segments);
      }

      bool
      open_rods() const override
      {
        return true;
      }

    protected:
      /// The geometry of the single open rod @p points.
      static GeneratedGeometry
      one_rod(std::vector<Vector3> points, const bool closed = false)
      {
        GeneratedGeometry geometry;
        geometry.rod_points.push_back(std::move(points));
        geometry.rod_closed.push_back(closed);
        return geometry;
      }
    };

    /// Declares "Radius" (of an arc, a ring or a helix).
    void
    declare_radius(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Radius",
                        "1",
                        Double(0),
                        "Arc, ring and helix: radius. [m]");
    }

    /// Declares "Center", "Radius" and the plane axes of a circle.
    /// Declares "Turns" (of a helix or a ring).
    void
    declare_turns(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Turns",
                        "1",
                        Double(0),
                        "Helix: number of turns; ring: how often it is "
                        "wound around the circle (a whole number). [-]");
    }

    void
    declare_circle(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Center",
                        "0, 0, 0",
                        vector_pattern(),
                        "Arc and ring: center of the circle. [m]");
      declare_radius(prm);
      prm.declare_entry("Plane axis 1",
                        "1, 0, 0",
                        vector_pattern(),
                        "Arc and ring: direction of the first in-plane "
                        "axis (normalized; angle 0). [-]");
      prm.declare_entry("Plane axis 2",
                        "0, 1, 0",
                        vector_pattern(),
                        "Arc and ring: direction of the second in-plane "
                        "axis (normalized; angle 90 deg), orthogonal to the "
                        "first. [-]");
    }

    /// The circle of "Center", "Radius" and the plane axes.
    struct Circle
    {
      Vector3 center;
      double  radius;
      Vector3 e1, e2;

      explicit Circle(const dealii::ParameterHandler &prm)
          : center(get_vector(prm, "Center"))
          , radius(prm.get_double("Radius"))
      {
        std::tie(e1, e2) = scene_entries::get_plane_axes(prm);
      }
    };

    class StraightGenerator : public OpenRodGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Start",
                          "0, 0, 0",
                          vector_pattern(),
                          "Straight rod: first end. [m]");
        prm.declare_entry("End",
                          "1, 0, 0",
                          vector_pattern(),
                          "Straight rod: second end. [m]");
      }

      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        return one_rod(generators::straight(get_vector(prm, "Start"),
                                            get_vector(prm, "End"),
                                            input.segments,
                                            input.midpoint_clamp));
      }
    };

    class ArcGenerator : public OpenRodGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_circle(prm);
        prm.declare_entry("Start angle",
                          "0",
                          Double(),
                          "Arc: angle of the first vertex. [deg]");
        prm.declare_entry("End angle",
                          "90",
                          Double(),
                          "Arc: angle of the last vertex. [deg]");
      }

      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        const Circle c(prm);
        return one_rod(generators::arc(c.center,
                                       c.radius,
                                       c.e1,
                                       c.e2,
                                       prm.get_double("Start angle") * degree,
                                       prm.get_double("End angle") * degree,
                                       input.segments,
                                       input.midpoint_clamp));
      }
    };

    class RingGenerator : public OpenRodGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_circle(prm);
        declare_turns(prm);
      }

      std::optional<ProblemSize>
      planned_size(const dealii::ParameterHandler &,
                   const GeneratorInput &input) const override
      {
        return rods_size(1, input.segments, 1);
      }

      bool
      open_rods() const override
      {
        return false;
      }

      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        const Circle c(prm);
        const double turns = prm.get_double("Turns");
        if (turns < 1 || turns != std::floor(turns))
          throw std::invalid_argument(
            "entry \"Geometry/Turns\": a ring is wound a whole number of "
            "times, at least once, not " +
            prm.get("Turns"));
        return one_rod(generators::ring(c.center,
                                        c.radius,
                                        c.e1,
                                        c.e2,
                                        input.segments,
                                        static_cast<unsigned int>(turns)),
                       true);
      }
    };

    class HelixGenerator : public OpenRodGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_radius(prm);
        prm.declare_entry("Rise per radian",
                          "0.1",
                          Double(),
                          "Helix: axial rise per radian of turn (the pitch "
                          "divided by 2 pi). [m]");
        declare_turns(prm);
      }

      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        return one_rod(generators::helix(prm.get_double("Radius"),
                                         prm.get_double("Rise per radian"),
                                         prm.get_double("Turns"),
                                         input.segments,
                                         input.midpoint_clamp));
      }
    };

    class PolylineGenerator : public OpenRodGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Points",
                          "0,0,0; 1,0,0",
                          Anything(),
                          "Polyline: corner points \"x,y,z; x,y,z; ...\". "
                          "[m]");
      }

      std::optional<ProblemSize>
      planned_size(const dealii::ParameterHandler &prm,
                   const GeneratorInput           &input) const override
      {
        // Unsigned: no points make the size too large to be built.
        const std::size_t pieces =
          dealii::Utilities::split_string_list(prm.get("Points"), ';').size() -
          1;
        return rods_size(1, double(input.segments) * pieces);
      }

      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        std::vector<Vector3> corners;
        for (const std::string &p :
             dealii::Utilities::split_string_list(prm.get("Points"), ';'))
          corners.push_back(corner(p));
        return one_rod(
          generators::polyline(corners, input.segments, input.midpoint_clamp));
      }

    private:
      /// The point "x,y,z" @p text.
      static Vector3
      corner(const std::string &text)
      {
        const auto xyz = dealii::Utilities::split_string_list(text, ',');
        try
          {
            if (xyz.size() != 3)
              throw std::invalid_argument("");
            const auto v = dealii::Utilities::string_to_double(xyz);
            return Vector3(v[0], v[1], v[2]);
          }
        catch (const std::exception &)
          {
            throw std::invalid_argument("entry \"Geometry/Points\": \"" + text +
                                        "\" is not a point x,y,z");
          }
      }
    };

    /// The rods of a Gmsh line mesh, one per physical tag.
    class GmshRodsGenerator : public GeometryGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        scene_entries::declare_mesh_file(prm);
      }

      bool
      open_rods() const override
      {
        return true;
      }

      std::vector<UnreadEntry>
      unread_shared_entries() const override
      {
        return {{"Segments", "the mesh's line elements are the segments"}};
      }

      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        GeneratedGeometry geometry;
        for (const RodChain &chain : read_gmsh_rods(
               scene_entries::get_file(prm, "Mesh file", input.scene_directory),
               &geometry.notes))
          {
            if (input.midpoint_clamp && chain.closed)
              throw std::invalid_argument(
                "entry \"Geometry/Clamp at first segment midpoint\": "
                "physical tag " +
                std::to_string(chain.tag) +
                " of the mesh is a closed chain with no start to clamp; "
                "set it to false");
            geometry.rod_points.push_back(
              input.midpoint_clamp ?
                generators::center_first_segment_on_start(chain.points) :
                chain.points);
            geometry.rod_closed.push_back(chain.closed);
          }
        return geometry;
      }
    };
  } // namespace

  void
  register_rod_generators(GeneratorRegistry &registry)
  {
    registry.add<StraightGenerator>("straight", "a straight rod");
    registry.add<ArcGenerator>("arc", "a circular arc");
    registry.add<RingGenerator>("ring", "a closed ring");
    registry.add<HelixGenerator>("helix", "a helix");
    registry.add<PolylineGenerator>("polyline",
                                    "a polyline through given points");
    registry.add<GmshRodsGenerator>(
      "gmsh",
      "the rods of a Gmsh line mesh (one rod per physical tag)");
  }
} // namespace rodnet
