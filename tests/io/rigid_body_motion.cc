// Energy and momenta of a network with rigid bodies (core/motion.h, the
// motion probes): in a rigid motion v = V + Omega x X, every body and rod
// moves as one rigid body, so the linear momentum is the total mass times
// the velocity of the centre of mass, the angular momentum sums each
// part's c x m v_c and its spin (a hub's j Omega, an end body's J_p Omega),
// and the kinetic energy their translational and rotational energies.
#include <deal.II/base/parameter_handler.h>

#include <core/mass_matrix.h>
#include <core/motion.h>
#include <io/scene.h>
#include <io/scene_file.h>

#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  /// Two beams of 4 segments welded at the node "hub" (0.3, 0.2, 0), to the
  /// free ends "a" (1.3, 0.2, 0) and "b" (0.3, 1.2, 0), rho A = 2; a hub
  /// of mass 0.7 and inertia 0.05, a body at "a" of mass 0.4, J_t = 0.01,
  /// J_p = 0.03, its centre 0.2 beyond the end, a point mass 0.3 at the
  /// middle of the second beam (0.3, 0.7, 0).
  std::string
  hub_network_scene(const std::string &bodies =
                      "@hub: mass 0.7 inertia 0.05; @a: mass 0.4 inertia "
                      "0.01,0.03 offset 0.2; 1:mid: mass 0.3",
                    const std::string &hub_kind = "")
  {
    const std::string file = RODNET_BINARY_DIR "/rigid_body_motion.net";
    std::ofstream(file) << "node hub 0.3 0.2 0 " << hub_kind
                        << "\nnode a 1.3 0.2 0\n"
                           "node b 0.3 1.2 0\nbeam hub a d1 0 0 1\n"
                           "beam hub b d1 0 0 1\n";
    return "subsection Geometry\n  set Generator = network file\n"
           "  set Network file = " +
           file +
           "\n  set Segments = 4\nend\n"
           "subsection Material\n  set Mass per length = 2\n"
           "  set Twist inertia per length = 1e-3\n"
           "  set Rotary inertia per length = 0\n"
           "  subsection linear elastic\n    set Stiffness input = direct\n"
           "    set EA = 1e3\n    set EI1 = 1\n    set EI2 = 1\n"
           "    set GJ = 1\n  end\nend\n"
           "subsection Loads\n  set Rigid bodies = " +
           bodies +
           "\nend\n"
           "subsection Solver\n  set Method = time stepping\n"
           "  subsection Time stepping\n    set Integrator = midpoint\n"
           "    set Time step = 0.01\n  end\nend\n";
  }

  /// The momenta and kinetic energy of a part of mass @p m, centre @p c,
  /// turning rigidly at Omega = (0, 0, omega) about the origin with the
  /// origin's velocity V, spin inertia @p spin about c (about z).
  struct Expected
  {
    Vector3 p = Vector3::Zero(), L = Vector3::Zero();
    double  K = 0;

    void
    add(const double   m,
        const Vector3 &c,
        const double   spin,
        const Vector3 &V,
        const Vector3 &Omega)
    {
      const Vector3 v = V + Omega.cross(c);
      p += m * v;
      L += c.cross(m * v) + spin * Omega;
      K += 0.5 * m * v.squaredNorm() + 0.5 * spin * Omega.squaredNorm();
    }

    /// A straight rod from @p x0 to @p x1 in the plane z = 0 of mass
    /// per length @p rho_A: about its centre, rho A l^3 / 12.
    void
    add_rod(const double   rho_A,
            const Vector3 &x0,
            const Vector3 &x1,
            const Vector3 &V,
            const Vector3 &Omega)
    {
      const double l = (x1 - x0).norm();
      add(rho_A * l, (x0 + x1) / 2, rho_A * l * l * l / 12, V, Omega);
    }
  };

  TEST(RigidBodyMotion, RigidMotionOfANetworkWithBodies)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm, hub_network_scene(), "scene", false);
    const Scene scene(prm);
    const auto  model = scene.build_model();
    MatrixType  mass;
    assemble_mass_matrix(*model, scene.inertia(), MassKind::consistent, mass);

    // v = V + Omega x X at every vertex, the junction turning at Omega
    // (omega = 2 adot at q = (1, 0)); Omega is normal to every tangent, so
    // no segment twists.
    const Vector3 V(0.3, -0.4, 1.2), Omega(0, 0, 0.8);
    VectorType    u = model->create_vector(), v = model->create_vector();
    for (unsigned int i = 0; i < model->network().n_vertices(); ++i)
      for (unsigned int c = 0; c < 3; ++c)
        v[model->layout().vertex_dof(i, c)] =
          (V + Omega.cross(model->network().vertex(i)))[c];
    for (unsigned int j = 0; j < model->network().junctions().size(); ++j)
      for (unsigned int c = 0; c < 3; ++c)
        v[model->layout().rotation_dof(j, c + 1)] = Omega[c] / 2;
    const Motion motion = motion_of(*model, mass, u, v, 0);

    const Vector3 hub(0.3, 0.2, 0), a(1.3, 0.2, 0), b(0.3, 1.2, 0);
    Expected      e;
    e.add_rod(2, hub, a, V, Omega);
    e.add_rod(2, hub, b, V, Omega);
    e.add(0.7, hub, 0.05, V, Omega);
    e.add(0.4, a + Vector3(0.2, 0, 0), 0.03, V, Omega);
    e.add(0.3, (hub + b) / 2, 0, V, Omega);
    const double scale = e.p.norm();
    for (unsigned int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(motion.linear_momentum[c], e.p[c], 1e-12 * scale) << c;
        EXPECT_NEAR(motion.angular_momentum[c], e.L[c], 1e-12 * scale) << c;
      }
    EXPECT_NEAR(motion.kinetic_energy, e.K, 1e-12 * e.K);
    // The total mass: 2 + 2 + 0.7 + 0.4 + 0.3.
    EXPECT_NEAR(e.p[2], 5.4 * V[2], 1e-12);
  }
  /// The message with which building the scene of @p bodies at a hub of
  /// kind @p hub_kind fails.
  std::string
  refusal(const std::string &bodies, const std::string &hub_kind)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm, hub_network_scene(bodies, hub_kind), "scene", false);
    try
      {
        const Scene scene(prm);
        scene.build_model();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "accepted";
  }

  // A junction has no tangent for an offset to follow, and a pinned one no
  // rotation for an inertia to turn with.
  TEST(RigidBodyMotion, RefusedAtJunctions)
  {
    EXPECT_EQ(refusal("@hub: mass 1 offset 0.1", ""),
              "entry \"Loads/Rigid bodies\": \"@hub\": the junction \"hub\" "
              "is no free rod end, and an offset needs the end's tangent to "
              "align with; give the isotropic \"inertia <j>\" alone there");
    EXPECT_EQ(refusal("@hub: mass 1 inertia 0.1", "pinned"),
              "entry \"Loads/Rigid bodies\": \"@hub\": a rotary inertia turns "
              "with a junction's rotation, and vertex 0 of rod 0 is in the "
              "pinned junction \"hub\", where each rod end turns on its own");
    EXPECT_EQ(refusal("@hub: mass 1", "pinned"), "accepted");
    // A centre off the vertex turns with the junction's rotation.
    EXPECT_EQ(refusal("@hub: mass 1 centre 0.1,0,0", "pinned"),
              "entry \"Loads/Rigid bodies\": \"@hub\": a centre off the "
              "vertex turns with a junction's rotation, and vertex 0 of rod 0 "
              "is in the pinned junction \"hub\", where each rod end turns on "
              "its own");
    EXPECT_EQ(refusal("@hub: mass 1 centre 0.1,0,0", ""), "accepted");
  }
} // namespace
