#include <core/configuration.h>
#include <families/developable_ribbon_family.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /**
     * The coefficients @p difference of eta' = (own, prev, next) . eta at
     * a hinge beside a ring's closure (@p before it: the closing hinge;
     * else the next one) with the closure coupling @p t: t of the central
     * difference in @p difference plus 1 - t of the one-sided one over the
     * segment @p l on this side, which leaves out the hinge beyond the
     * closure.
     */
    void
    couple_across_closure(std::vector<double> &difference,
                          const double         t,
                          const bool           before,
                          const double         l)
    {
      if (before) // (eta_own - eta_prev) / l
        {
          difference[0] = (1 - t) / l;
          difference[1] = t * difference[1] - (1 - t) / l;
          difference[2] *= t;
        }
      else // (eta_next - eta_own) / l
        {
          difference[0] = -(1 - t) / l;
          difference[1] *= t;
          difference[2] = t * difference[2] + (1 - t) / l;
        }
    }

    /// In ribbon_hinge_at_vertex(): no ribbon hinge at the vertex.
    constexpr unsigned int no_ribbon_hinge = static_cast<unsigned int>(-1);

    /// Per vertex of @p network, the hinge of @p layout on a developable
    /// rod centred there, or no_ribbon_hinge: the neighbours whose eta
    /// enter a hinge's eta'.
    std::vector<unsigned int>
    ribbon_hinge_at_vertex(const DofLayout &layout, const RodNetwork &network)
    {
      const auto               &hinges = layout.hinges();
      std::vector<unsigned int> hinge_at(network.n_vertices(), no_ribbon_hinge);
      for (unsigned int h = 0; h < hinges.size(); ++h)
        if (network.rods()[hinges[h].rod].developable)
          hinge_at[hinges[h].vertices[1]] = h;
      return hinge_at;
    }

    /// Per vertex of @p network, its index along its rod (for labels).
    std::vector<unsigned int>
    indices_along_rods(const RodNetwork &network)
    {
      std::vector<unsigned int> along(network.n_vertices(), 0);
      for (const Rod &rod : network.rods())
        for (unsigned int k = 0; k < rod.vertices.size(); ++k)
          along[rod.vertices[k]] = k;
      return along;
    }

    /**
     * Throws unless @p hinge (index @p h) has no natural strains. The
     * developability constraints hold for a strip that is flat and
     * straight when unstressed; a natural curvature or twist would
     * silently turn them into constraints on the strains' change.
     */
    void
    check_flat_at_rest(const Configuration &configuration,
                       const HingeStencil  &hinge,
                       const unsigned int   h)
    {
      if (configuration.natural_strains(h).norm() > 1e-12)
        throw std::invalid_argument(
          "rod " + std::to_string(hinge.rod) +
          ": a developable ribbon is straight and flat when unstressed, "
          "but its hinge at vertex " +
          std::to_string(hinge.vertices[1]) +
          " has natural strains; set \"Geometry/Natural shape = "
          "straight\"");
    }

    /// Local DoFs of a ribbon stencil: the hinge's, up to three etas and
    /// the two multipliers.
    constexpr int max_ribbon_dofs = n_hinge_dofs + 3 + 2;
    using RibbonVector =
      Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_ribbon_dofs, 1>;
    using RibbonMatrix = Eigen::Matrix<double,
                                       Eigen::Dynamic,
                                       Eigen::Dynamic,
                                       0,
                                       max_ribbon_dofs,
                                       max_ribbon_dofs>;
    /// The Lagrangian's variables z = (c_1, c_2, c_3, eta, eta', mu_2,
    /// mu_3).
    using ZVector = Eigen::Matrix<double, 7, 1>;
    using ZMatrix = Eigen::Matrix<double, 7, 7>;

    /// The ribbon's Lagrangian at a hinge as a function of the strains
    /// (DevelopableRibbonFamily): at() evaluates the law at kappa and
    /// returns dL/dc, the weights of the kernel's strain Hessians.
    struct RibbonLagrangian : StrainWeights
    {
      RibbonLagrangian(const DevelopableRibbonLaw &law,
                       const Eigen::Vector4d      &variables,
                       const double                voronoi_length)
          : law(law)
          , eta(variables[0])
          , eta_prime(variables[1])
          , mu_2(variables[2])
          , mu_3(variables[3])
          , length(voronoi_length)
          , scale(law.bending_modulus() / (voronoi_length * voronoi_length))
      {
      }

      Vector3
      at(const Vector3 &kappa) const override
      {
        c        = kappa;
        response = law.energy(c[0], eta, eta_prime, length);
        weights  = {response.gradient[0] - scale * mu_3 * eta,
                    scale * mu_2,
                    scale * mu_3};
        return weights;
      }

      /// The Lagrangian at the strains at() was last asked at.
      double
      value() const
      {
        return response.energy +
               scale * (mu_2 * c[1] + mu_3 * (c[2] - eta * c[0]));
      }

      /// dL/dz at the same strains.
      ZVector
      gradient() const
      {
        ZVector g;
        g.head<3>() = weights;
        g[3]        = response.gradient[1] - scale * mu_3 * c[0];
        g[4]        = response.gradient[2];
        g[5]        = scale * c[1];
        g[6]        = scale * (c[2] - eta * c[0]);
        return g;
      }

      /// d^2L/dz^2 at the same strains.
      ZMatrix
      hessian() const
      {
        ZMatrix                  h   = ZMatrix::Zero();
        const std::array<int, 3> map = {{0, 3, 4}};
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            h(map[a], map[b]) = response.hessian(a, b);
        const auto add = [&h](const int i, const int j, const double v) {
          h(i, j) += v;
          h(j, i) += v;
        };
        add(0, 3, -scale * mu_3);
        add(0, 6, -scale * eta);
        add(3, 6, -scale * c[0]);
        add(1, 5, scale);
        add(2, 6, scale);
        return h;
      }

      const DevelopableRibbonLaw &law;
      const double                eta, eta_prime, mu_2, mu_3, length, scale;
      mutable Vector3             c;
      mutable Vector3             weights; ///< dL/dc, at()
      mutable DevelopableRibbonLaw::Response response;
    };
  } // namespace


  DevelopableRibbonFamily::DevelopableRibbonFamily(
    const DofLayout                                       &layout,
    const RodNetwork                                      &network,
    const Configuration                                   &configuration,
    const std::vector<std::unique_ptr<HingeKernel>>       &kernels,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials)
      : layout(layout)
      , kernels(kernels)
  {
    const auto                     &hinges = layout.hinges();
    const std::vector<unsigned int> hinge_at =
      ribbon_hinge_at_vertex(layout, network);
    const std::vector<unsigned int> along = indices_along_rods(network);
    // The block: three DoFs per ribbon hinge, in the order of the hinges.
    first_of_hinge.assign(hinges.size(), dealii::numbers::invalid_dof_index);
    global_dof_index n_own = 0;
    for (unsigned int h = 0; h < hinges.size(); ++h)
      if (network.rods()[hinges[h].rod].developable)
        {
          first_of_hinge[h] = n_own;
          n_own += 3;
        }
    for (unsigned int h = 0; h < hinges.size(); ++h)
      {
        if (first_of_hinge[h] == dealii::numbers::invalid_dof_index)
          continue;
        const HingeStencil &hinge = hinges[h];
        Stencil             stencil;
        stencil.hinge     = h;
        stencil.along_rod = along[hinge.vertices[1]];
        stencil.law       = materials[hinge.rod]->developable_ribbon();
        if (stencil.law == nullptr)
          throw std::logic_error("rod " + std::to_string(hinge.rod) +
                                 " is developable, its material is not");
        set_eta_difference(stencil, hinge_at, network, configuration);
        check_flat_at_rest(configuration, hinge, h);
        stencil.drag = drag_factor * stencil.law->bending_modulus() /
                       configuration.voronoi_length(h);
        stencils.push_back(std::move(stencil));
      }
  }


  void
  DevelopableRibbonFamily::set_eta_difference(
    Stencil                         &stencil,
    const std::vector<unsigned int> &hinge_at,
    const RodNetwork                &network,
    const Configuration             &configuration) const
  {
    const auto         &hinges = layout.hinges();
    const unsigned int  h      = stencil.hinge;
    const HingeStencil &hinge  = hinges[h];
    unsigned int        prev   = hinge_at[hinge.vertices[0]];
    unsigned int        next   = hinge_at[hinge.vertices[2]];
    if (prev == next) // a closed rod of two segments
      next = no_ribbon_hinge;
    const bool has_prev = prev != no_ribbon_hinge;
    const bool has_next = next != no_ribbon_hinge;
    // Across the closure of a Moebius band eta changes sign.
    const double prev_sign =
      has_prev && configuration.closes_with_a_flip(hinges[prev]) ? -1 : 1;
    const double next_sign = configuration.closes_with_a_flip(hinge) ? -1 : 1;
    const double l_prev    = configuration.rest_length(hinge.segment_prev);
    const double l_next    = configuration.rest_length(hinge.segment_next);
    stencil.etas           = {first_of_hinge[h]};
    stencil.difference     = {0.0};
    const double span = (has_prev ? l_prev : 0.0) + (has_next ? l_next : 0.0);
    if (has_prev)
      {
        stencil.etas.push_back(first_of_hinge[prev]);
        stencil.difference.push_back(-prev_sign / span);
      }
    if (has_next)
      {
        stencil.etas.push_back(first_of_hinge[next]);
        stencil.difference.push_back(next_sign / span);
      }
    // One-sided at an end: the hinge's own eta takes the missing
    // neighbour's place.
    if (!has_prev && has_next)
      stencil.difference[0] = -1 / span;
    if (!has_next && has_prev)
      stencil.difference[0] = 1 / span;
    const double t = network.rods()[hinge.rod].closure_coupling;
    if (t < 1 && has_prev && has_next)
      {
        if (configuration.closes(hinge))
          couple_across_closure(stencil.difference, t, true, l_prev);
        if (configuration.closes(hinges[prev]))
          couple_across_closure(stencil.difference, t, false, l_next);
      }
  }


  void
  DevelopableRibbonFamily::get_dofs(const unsigned int             s,
                                    std::vector<global_dof_index> &dofs) const
  {
    const Stencil &stencil = stencils[s];
    const auto    &hinge   = layout.hinges()[stencil.hinge].dofs;
    dofs.assign(hinge.begin(), hinge.end());
    dofs.insert(dofs.end(), stencil.etas.begin(), stencil.etas.end());
    dofs.push_back(first_of_hinge[stencil.hinge] + 1);
    dofs.push_back(first_of_hinge[stencil.hinge] + 2);
  }


  std::vector<DeclaredDof>
  DevelopableRibbonFamily::own_dofs() const
  {
    std::vector<DeclaredDof> dofs;
    for (const Stencil &stencil : stencils)
      {
        const HingeStencil &hinge = layout.hinges()[stencil.hinge];
        const std::string   place = "rod " + std::to_string(hinge.rod) +
                                  " vertex " +
                                  std::to_string(stencil.along_rod);
        DeclaredDof slope;
        slope.role   = DofRole::shape;
        slope.vertex = hinge.vertices[1];
        slope.label  = place + " (its generatrix slope)";
        dofs.push_back(slope);
        DeclaredDof developability = slope;
        developability.role        = DofRole::multiplier;
        developability.label       = place + " (its developability)";
        developability.held_where_supports_hold = true;
        dofs.push_back(developability);
        dofs.push_back(developability);
      }
    return dofs;
  }


  bool
  DevelopableRibbonFamily::applies_to(const RodNetwork &network)
  {
    return network.any_rod(&Rod::developable);
  }


  void
  DevelopableRibbonFamily::number_own_dofs(const global_dof_index first)
  {
    for (global_dof_index &start : first_of_hinge)
      if (start != dealii::numbers::invalid_dof_index)
        start += first;
    for (Stencil &stencil : stencils)
      for (global_dof_index &eta : stencil.etas)
        eta += first;
  }


  Eigen::Vector4d
  DevelopableRibbonFamily::ribbon_variables(const Stencil      &stencil,
                                            const StencilState &state) const
  {
    double eta_prime = 0;
    for (unsigned int j = 0; j < stencil.etas.size(); ++j)
      eta_prime += stencil.difference[j] * state.u[stencil.etas[j]];
    return {state.u[stencil.etas[0]],
            eta_prime,
            state.u[first_of_hinge[stencil.hinge] + 1],
            state.u[first_of_hinge[stencil.hinge] + 2]};
  }


  double
  DevelopableRibbonFamily::drag(const unsigned int s) const
  {
    return stencils[s].drag;
  }


  void
  DevelopableRibbonFamily::evaluate(const unsigned int  s,
                                    const StencilState &state,
                                    const Derivatives   derivatives,
                                    LocalContribution  &local) const
  {
    const Stencil         &stencil   = stencils[s];
    const HingeStencil    &hinge     = layout.hinges()[stencil.hinge];
    const Configuration   &config    = state.configuration;
    const HingeKernel     &kernel    = *kernels[hinge.rod];
    const HingeVector      x         = config.hinge_dofs(state.u, hinge);
    const HingeReference  &reference = config.hinge_reference(stencil.hinge);
    const RibbonLagrangian lagrangian(*stencil.law,
                                      ribbon_variables(stencil, state),
                                      config.voronoi_length(stencil.hinge));
    if (derivatives == Derivatives::energy)
      {
        lagrangian.at(kernel.strains(x, reference));
        local.energy = lagrangian.value();
        return;
      }

    // z = (c, eta, eta', mu) as a function of the local DoFs: J = dz/dy.
    const int                 m = stencil.etas.size();
    const int                 n = n_hinge_dofs + m + 2;
    thread_local HingeStrains strains;
    HingeMatrix               weighted;
    // The weighted evaluation asks the Lagrangian at the strains itself.
    if (derivatives == Derivatives::gradient)
      {
        kernel.evaluate(x, reference, strains, false);
        lagrangian.at(strains.kappa);
      }
    else
      kernel.evaluate_weighted(x, reference, lagrangian, strains, weighted);
    local.energy = lagrangian.value();

    Eigen::Matrix<double, 7, Eigen::Dynamic, 0, 7, max_ribbon_dofs> J =
      Eigen::Matrix<double, 7, Eigen::Dynamic, 0, 7, max_ribbon_dofs>::Zero(7,
                                                                            n);
    J.block<3, n_hinge_dofs>(0, 0) = strains.gradient;
    J(3, n_hinge_dofs)             = 1;
    for (int j = 0; j < m; ++j)
      J(4, n_hinge_dofs + j) = stencil.difference[j];
    J(5, n_hinge_dofs + m)     = 1;
    J(6, n_hinge_dofs + m + 1) = 1;

    const RibbonVector gradient = J.transpose() * lagrangian.gradient();
    if (derivatives == Derivatives::gradient)
      {
        local.store(gradient, static_cast<const RibbonMatrix *>(nullptr));
        return;
      }
    RibbonMatrix hessian = J.transpose() * lagrangian.hessian() * J;
    hessian.topLeftCorner<n_hinge_dofs, n_hinge_dofs>() += weighted;
    hessian(n_hinge_dofs, n_hinge_dofs) += drag(s);
    local.store(gradient, &hessian);
  }
} // namespace rodnet
