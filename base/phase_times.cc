#include <deal.II/base/array_view.h>

#include <base/phase_times.h>

#include <iomanip>

namespace rodnet
{
  namespace phase_times
  {
    namespace
    {
      using Clock = std::chrono::steady_clock;

      constexpr std::size_t n_phases =
        static_cast<std::size_t>(Phase::n_phases);

      /// One thread's accounts: the seconds per phase, the phase open now
      /// (Phase::n_phases for none) and when its clock last started.
      struct Accounts
      {
        std::array<double, n_phases> seconds{};
        Phase                        open = Phase::n_phases;
        Clock::time_point            since;

        /// Charges the time since the last event to the open phase and
        /// restarts the clock; then @p next is the open phase.
        void
        switch_to(const Phase next)
        {
          const Clock::time_point now = Clock::now();
          if (open != Phase::n_phases)
            seconds[static_cast<std::size_t>(open)] +=
              std::chrono::duration<double>(now - since).count();
          since = now;
          open  = next;
        }
      };

      Accounts &
      accounts()
      {
        thread_local Accounts these;
        return these;
      }
    } // namespace


    const char *
    name(const Phase phase)
    {
      static constexpr std::array<const char *, n_phases> names = {
        {"model build",
         "energy assembly",
         "gradient assembly",
         "Hessian assembly",
         "exchange and waiting",
         "factorization analysis",
         "numeric factorization",
         "linear solves",
         "checks",
         "outputs"}};
      return names[static_cast<std::size_t>(phase)];
    }


    Scope::Scope(const Phase phase)
        : outer(accounts().open)
    {
      accounts().switch_to(phase);
    }


    Scope::~Scope()
    {
      accounts().switch_to(outer);
    }


    std::array<double, n_phases>
    seconds()
    {
      return accounts().seconds;
    }


    void
    reset()
    {
      accounts().seconds.fill(0.);
    }


    void
    write_table(std::ostream  &out,
                const double   total_seconds,
                const MPI_Comm communicator)
    {
      const std::array<double, n_phases>    own = seconds();
      std::array<double, n_phases>          least{};
      std::array<double, n_phases>          most{};
      const dealii::ArrayView<const double> own_view(own.data(), n_phases);
      dealii::Utilities::MPI::min(own_view,
                                  communicator,
                                  dealii::ArrayView<double>(least.data(),
                                                            n_phases));
      dealii::Utilities::MPI::max(own_view,
                                  communicator,
                                  dealii::ArrayView<double>(most.data(),
                                                            n_phases));
      double charged = 0;
      for (const double s : own)
        charged += s;
      const double rest_least =
        dealii::Utilities::MPI::min(total_seconds - charged, communicator);
      const double rest_most =
        dealii::Utilities::MPI::max(total_seconds - charged, communicator);
      if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
        return;

      const auto row = [&](const char *label, double low, double high) {
        out << "  " << std::left << std::setw(24) << label << std::right
            << std::fixed << std::setprecision(3) << std::setw(10) << low
            << std::setw(10) << high << std::setprecision(1) << std::setw(8)
            << (total_seconds > 0 ? 100 * high / total_seconds : 0.) << " %"
            << std::defaultfloat << '\n';
      };
      out << "where the time went (wall seconds, least and most over the "
          << dealii::Utilities::MPI::n_mpi_processes(communicator)
          << " process(es), of " << std::fixed << std::setprecision(3)
          << total_seconds << std::defaultfloat << " s):\n"
          << "  " << std::left << std::setw(24) << "phase" << std::right
          << std::setw(10) << "least" << std::setw(10) << "most"
          << std::setw(10) << "share" << '\n';
      for (std::size_t p = 0; p < n_phases; ++p)
        if (most[p] >= 5e-4) // not shown as 0.000
          row(name(static_cast<Phase>(p)), least[p], most[p]);
      row("other", rest_least, rest_most);
      out << std::flush;
    }
  } // namespace phase_times
} // namespace rodnet
