#include <deal.II/base/utilities.h>

#include <geometry/network_generators.h>
#include <io/block_map.h>
#include <io/gmsh_network.h>
#include <io/network_file.h>
#include <io/network_generator_entries.h>
#include <io/scene_entries.h>

namespace rodnet
{
  namespace
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;

    /// The shared Geometry entries that no network generator reads.
    std::vector<UnreadEntry>
    entries_a_network_does_not_read()
    {
      return {{"Director d1",
               "a network orients each beam itself, with d1 = e_z (for a "
               "beam along z the coordinate axis least aligned with it) "
               "unless the beam gives its own (a network file's \"d1 <x> "
               "<y> <z>\", the frame's and the windmill's beams) or its "
               "group does (\"Group <name>/Director d1\", \"Group "
               "all/Director d1\" for every beam; doc/networks.md)"}};
    }

    /// A generator of a network of beams.
    class NetworkGenerator : public GeometryGenerator
    {
    public:
      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        GeneratedGeometry geometry;
        geometry.graph = graph(prm, input);
        return geometry;
      }

      std::vector<UnreadEntry>
      unread_shared_entries() const override
      {
        return entries_a_network_does_not_read();
      }

    protected:
      /// The beams and junctions of the network.
      virtual RodGraph
      graph(const dealii::ParameterHandler &prm,
            const GeneratorInput           &input) const = 0;
    };

    /// A network of beams of one length, "Beam length".
    class BeamLengthNetwork : public NetworkGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Beam length",
                          "1",
                          Double(0),
                          "Networks: leg length of the frame, shaft length "
                          "of the windmill, cell side of the lattices. [m]");
      }
    };

    class FrameGenerator : public BeamLengthNetwork
    {
      RodGraph
      graph(const dealii::ParameterHandler &prm,
            const GeneratorInput &) const override
      {
        return network_generators::right_angle_frame(
          prm.get_double("Beam length"));
      }
    };

    class WindmillGenerator : public BeamLengthNetwork
    {
      RodGraph
      graph(const dealii::ParameterHandler &prm,
            const GeneratorInput &) const override
      {
        return network_generators::windmill(prm.get_double("Beam length"));
      }
    };

    /// A lattice of "Cells" cells of side "Beam length"; its size is
    /// known from these before it is generated.
    class LatticeGenerator : public BeamLengthNetwork
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        BeamLengthNetwork::declare_parameters(prm);
        prm.declare_entry("Cells",
                          "2, 2",
                          dealii::Patterns::List(Integer(1), 2, 2, ","),
                          "Lattices: number of cells along x and y. [-]");
      }

      std::string
      size_entry() const override
      {
        return "Geometry/Cells";
      }

    protected:
      /// "Cells" along x and y.
      static std::pair<unsigned int, unsigned int>
      cells(const dealii::ParameterHandler &prm)
      {
        const auto n = dealii::Utilities::string_to_int(
          dealii::Utilities::split_string_list(prm.get("Cells"), ','));
        return {n[0], n[1]};
      }
    };

    class SquareLatticeGenerator : public LatticeGenerator
    {
      std::optional<ProblemSize>
      planned_size(const dealii::ParameterHandler &prm,
                   const GeneratorInput           &input) const override
      {
        const auto [nx, ny] = cells(prm);
        // The sides of (nx + 1)(ny + 1) nodes.
        return network_size(double(nx) * (ny + 1.) + double(ny) * (nx + 1.),
                            (nx + 1.) * (ny + 1.),
                            input.segments);
      }

      RodGraph
      graph(const dealii::ParameterHandler &prm,
            const GeneratorInput &) const override
      {
        const auto [nx, ny] = cells(prm);
        return network_generators::square_lattice(nx,
                                                  ny,
                                                  prm.get_double(
                                                    "Beam length"));
      }
    };

    class HexagonalLatticeGenerator : public LatticeGenerator
    {
      std::optional<ProblemSize>
      planned_size(const dealii::ParameterHandler &prm,
                   const GeneratorInput           &input) const override
      {
        const double nx = cells(prm).first, ny = cells(prm).second;
        // 3 new sides per cell and 2 more at the rim, 2 corners per cell
        // and 2 more.
        return network_size(3 * nx * ny + 2 * (nx + ny),
                            2 * nx * ny + 2 * (nx + ny),
                            input.segments);
      }

      RodGraph
      graph(const dealii::ParameterHandler &prm,
            const GeneratorInput &) const override
      {
        const auto [nx, ny] = cells(prm);
        return network_generators::hexagonal_lattice(nx,
                                                     ny,
                                                     prm.get_double(
                                                       "Beam length"));
      }
    };

    class NetworkFileGenerator : public NetworkGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Network file",
                          "",
                          dealii::Patterns::Anything(),
                          "Network file: path of the node/beam list, "
                          "relative to the scene file. [-]");
      }

      RodGraph
      graph(const dealii::ParameterHandler &prm,
            const GeneratorInput           &input) const override
      {
        return read_network_file(
          scene_entries::get_file(prm, "Network file", input.scene_directory));
      }
    };

    /// A network of the mesh's line elements; what the reader says of the
    /// mesh goes with it.
    class GmshNetworkGenerator : public GeometryGenerator
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        scene_entries::declare_mesh_file(prm);
      }

      GeneratedGeometry
      generate(const dealii::ParameterHandler &prm,
               const GeneratorInput           &input) const override
      {
        GeneratedGeometry geometry;
        geometry.graph = read_gmsh_network(
          scene_entries::get_file(prm, "Mesh file", input.scene_directory),
          &geometry.notes);
        return geometry;
      }

      std::vector<UnreadEntry>
      unread_shared_entries() const override
      {
        return entries_a_network_does_not_read();
      }
    };
  } // namespace

  void
  register_network_generators(GeneratorRegistry &registry)
  {
    registry.add<FrameGenerator>(
      "frame",
      "the right-angle frame of Lestringant & Kochmann (Fig. 3)");
    registry.add<WindmillGenerator>(
      "windmill",
      "the windmill of Lestringant & Kochmann (Fig. 3)");
    registry.add<SquareLatticeGenerator>("square lattice", "a square lattice");
    registry.add<HexagonalLatticeGenerator>("hexagonal lattice",
                                            "a hexagonal lattice");
    registry.add<NetworkFileGenerator>("network file", "a node/beam list file");
    registry.add<GmshNetworkGenerator>("gmsh network",
                                       "a branched Gmsh line mesh");
    registry.add<BlockMapGenerator>("block map", "blocks of a block map file");
  }
} // namespace rodnet
