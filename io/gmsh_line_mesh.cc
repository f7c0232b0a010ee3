#include <geometry/rod_graph.h>
#include <io/gmsh_line_mesh.h>

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// How many sets of merged nodes or chains a message names.
    constexpr std::size_t n_named = 5;

    /// The tags of the nodes that elements use, in increasing order.
    std::vector<long>
    used_nodes(const GmshLineMesh &mesh)
    {
      std::set<long> used;
      for (const GmshLineElement &line : mesh.lines)
        used.insert(line.nodes, line.nodes + 2);
      for (const auto &[node, points] : mesh.node_points)
        if (mesh.nodes.count(node) > 0)
          used.insert(node);
      return std::vector<long>(used.begin(), used.end());
    }

    /// Sets of indices, each represented by its lowest index.
    class DisjointSets
    {
    public:
      explicit DisjointSets(const std::size_t n)
          : parent(n)
      {
        std::iota(parent.begin(), parent.end(), std::size_t(0));
      }

      std::size_t
      root(std::size_t i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }

      void
      unite(const std::size_t a, const std::size_t b)
      {
        const std::size_t ra = root(a), rb = root(b);
        parent[std::max(ra, rb)] = std::min(ra, rb);
      }

    private:
      std::vector<std::size_t> parent;
    };

    /// The size of the bounding box of @p points along each axis.
    Vector3
    extent(const std::vector<Vector3> &points)
    {
      Vector3 low = points.front(), high = low;
      for (const Vector3 &p : points)
        {
          low  = low.cwiseMin(p);
          high = high.cwiseMax(p);
        }
      return high - low;
    }

    /// Calls @p pair(a, b, distance) for the points @p a, @p b of
    /// @p points closer than @p reach. Sorting along the axis of largest
    /// extent keeps the search near O(n log n).
    template <class Pair>
    void
    for_each_close_pair(const std::vector<Vector3> &points,
                        const double                reach,
                        const Pair                 &pair)
    {
      unsigned int axis = 0;
      extent(points).maxCoeff(&axis);
      std::vector<std::size_t> order(points.size());
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return points[a][axis] < points[b][axis];
      });
      for (std::size_t a = 0; a < order.size(); ++a)
        for (std::size_t b = a + 1;
             b < order.size() &&
             points[order[b]][axis] - points[order[a]][axis] <= reach;
             ++b)
          if (const double d = (points[order[a]] - points[order[b]]).norm();
              d <= reach)
            pair(order[a], order[b], d);
    }

    /// The length of the shortest line element of @p mesh longer than
    /// @p tolerance (0 if none is).
    double
    shortest_element(const GmshLineMesh &mesh, const double tolerance)
    {
      double shortest = 0;
      for (const GmshLineElement &line : mesh.lines)
        {
          const double length =
            (mesh.nodes.at(line.nodes[0]) - mesh.nodes.at(line.nodes[1]))
              .norm();
          if (length > tolerance && (shortest == 0 || length < shortest))
            shortest = length;
        }
      return shortest;
    }

    /// @p x to three significant digits, for messages (a name of its own:
    /// unity batches put this file beside users of scene_entries::number).
    std::string
    three_digits(const double x)
    {
      std::ostringstream text;
      text << std::setprecision(3) << x;
      return text.str();
    }

    /// Points the elements and physical points of the nodes in @p kept_of
    /// (merged tag -> kept tag) at the kept nodes, and removes the merged.
    void
    renumber(GmshLineMesh               &mesh,
             const std::map<long, long> &kept_of,
             const std::string          &path)
    {
      for (GmshLineElement &line : mesh.lines)
        {
          const long a = line.nodes[0], b = line.nodes[1];
          for (long &node : line.nodes)
            if (const auto it = kept_of.find(node); it != kept_of.end())
              node = it->second;
          if (line.nodes[0] == line.nodes[1])
            throw std::invalid_argument(
              "mesh \"" + path + "\": element " + std::to_string(line.tag) +
              " joins nodes " + std::to_string(a) + " and " +
              std::to_string(b) + ", which coincide (" +
              three_digits((mesh.nodes.at(a) - mesh.nodes.at(b)).norm()) +
              " apart, within " + three_digits(mesh.merge_tolerance) +
              " m): a line element of zero length; remove it");
        }
      for (const auto &[merged, kept] : kept_of)
        {
          if (const auto it = mesh.node_points.find(merged);
              it != mesh.node_points.end())
            {
              mesh.node_points[kept].insert(it->second.begin(),
                                            it->second.end());
              mesh.node_points.erase(merged);
            }
          mesh.nodes.erase(merged);
        }
    }
  } // namespace

  void
  merge_coincident_nodes(GmshLineMesh &mesh, const std::string &path)
  {
    const std::vector<long> tags = used_nodes(mesh);
    if (tags.empty())
      return;
    std::vector<Vector3> points;
    for (const long tag : tags)
      points.push_back(mesh.nodes.at(tag));
    const double tolerance = coincident_node_tolerance * extent(points).norm();
    mesh.merge_tolerance   = tolerance;
    // Nodes a little farther apart than that are no more likely distinct:
    // they are refused up to a small fraction of the shortest element.
    const double shortest = shortest_element(mesh, tolerance);
    DisjointSets sets(tags.size());
    for_each_close_pair(
      points,
      std::max(tolerance, 1e-3 * shortest),
      [&](const std::size_t a, const std::size_t b, const double distance) {
        if (distance <= tolerance)
          return sets.unite(a, b);
        throw std::invalid_argument(
          "mesh \"" + path + "\": nodes " +
          std::to_string(std::min(tags[a], tags[b])) + " and " +
          std::to_string(std::max(tags[a], tags[b])) + " are " +
          three_digits(distance) + " m apart: too far to be merged (within " +
          three_digits(tolerance) +
          " m) and too close to be distinct (less than 1e-3 times the "
          "shortest line element, " +
          three_digits(shortest) +
          " m); write them as one node if they are one joint (Gmsh: "
          "Coherence Mesh), or move them apart");
      });

    // Tags ascend, so each set's root is its lowest tag.
    std::map<long, std::vector<long>> set_of;
    std::map<long, long>              kept_of;
    for (std::size_t i = 0; i < tags.size(); ++i)
      if (const std::size_t r = sets.root(i); r != i)
        {
          auto &set = set_of[tags[r]];
          if (set.empty())
            set.push_back(tags[r]);
          set.push_back(tags[i]);
          kept_of[tags[i]] = tags[r];
        }
    for (auto &[kept, set] : set_of)
      mesh.merged_nodes.push_back(std::move(set));
    renumber(mesh, kept_of, path);
  }

  std::string
  merged_nodes_note(const GmshLineMesh &mesh, const std::string &path)
  {
    if (mesh.merged_nodes.empty())
      return "";
    std::ostringstream text;
    text << "mesh \"" << path << "\": merged coincident nodes (within "
         << three_digits(mesh.merge_tolerance) << " m, "
         << three_digits(coincident_node_tolerance)
         << " of the diagonal of the mesh's bounding box):";
    for (std::size_t s = 0; s < std::min(n_named, mesh.merged_nodes.size());
         ++s)
      {
        const std::vector<long> &set = mesh.merged_nodes[s];
        text << (s == 0 ? " " : "; ") << (set.size() > 2 ? "nodes " : "node ");
        for (std::size_t k = 1; k < set.size(); ++k)
          text << (k == 1              ? "" :
                   k + 1 == set.size() ? " and " :
                                         ", ")
               << set[k];
        text << " into node " << set[0];
      }
    if (mesh.merged_nodes.size() > n_named)
      text << "; and " << mesh.merged_nodes.size() - n_named << " more sets";
    return text.str();
  }

  std::string
  one_hinge_warning(const std::string              &path,
                    const std::vector<std::string> &chains,
                    const std::string              &advice)
  {
    if (chains.empty())
      return "";
    std::ostringstream text;
    text << "mesh \"" << path << "\": ";
    if (chains.size() == 1)
      text << chains[0]
           << " is a chain of two line elements, whose one hinge gives a "
              "first-order answer; the mesh decides its segments: ";
    else
      {
        text << chains.size()
             << " rods are chains of two line elements, whose one hinge "
                "gives a first-order answer: ";
        for (std::size_t c = 0; c < std::min(n_named, chains.size()); ++c)
          text << (c == 0 ? "" : ", ") << chains[c];
        if (chains.size() > n_named)
          text << " and " << chains.size() - n_named << " more";
        text << "; the mesh decides their segments: ";
      }
    text << advice;
    return text.str();
  }
} // namespace rodnet
