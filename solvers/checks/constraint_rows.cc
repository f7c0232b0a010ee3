#include <solvers/checks/constraint_rows.h>

namespace rodnet
{
  std::vector<ConstraintRow>
  constraint_rows(const SolvableModel &model,
                  const DofRoles      &roles,
                  const VectorType    &u)
  {
    using Kind = DofRoles::Kind;
    std::vector<ConstraintRow>    rows;
    std::vector<global_dof_index> dofs;
    LocalContribution             local;
    const StencilState            state{u,
                             model.configuration(),
                             model.internal_variables(),
                             model.time_step(),
                             model.applied_load_factor(0)};
    for (const auto &family : model.element_families())
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          family->get_dofs(s, dofs);
          bool constrained = false;
          for (const global_dof_index d : dofs)
            constrained = constrained || roles.kind(d) == Kind::multiplier;
          if (!constrained)
            continue;
          local.dofs = dofs;
          family->evaluate(s, state, Derivatives::hessian, local);
          for (unsigned int a = 0; a < dofs.size(); ++a)
            if (roles.kind(dofs[a]) == Kind::multiplier)
              {
                ConstraintRow row{dofs, std::vector<double>(dofs.size())};
                for (unsigned int b = 0; b < dofs.size(); ++b)
                  row.gradient[b] = local.matrix(a, b);
                rows.push_back(std::move(row));
              }
        }
    return rows;
  }
} // namespace rodnet
