#include <deal.II/base/mpi.h>

#include <base/phase_times.h>

#include <algorithm>
#include <iomanip>
#include <vector>

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


    namespace
    {
      /// One row of the table: the least and the most seconds over the
      /// processes and the rank of a process that took the most.
      struct Spread
      {
        double       least   = 0;
        double       most    = 0;
        unsigned int slowest = 0;
      };

      /// The spread over the processes of each of @p own's entries (this
      /// process's), on rank 0 of @p communicator (empty elsewhere).
      std::vector<Spread>
      spread_over_processes(const std::vector<double> &own,
                            const MPI_Comm             communicator)
      {
        const std::vector<std::vector<double>> all =
          dealii::Utilities::MPI::gather(communicator, own, 0);
        std::vector<Spread> spreads;
        for (std::size_t k = 0; k < own.size() && !all.empty(); ++k)
          {
            Spread spread{all[0][k], all[0][k], 0};
            for (unsigned int rank = 1; rank < all.size(); ++rank)
              {
                spread.least = std::min(spread.least, all[rank][k]);
                if (all[rank][k] > spread.most)
                  spread = {spread.least, all[rank][k], rank};
              }
            spreads.push_back(spread);
          }
        return spreads;
      }
    } // namespace


    void
    write_table(std::ostream  &out,
                const double   total_seconds,
                const MPI_Comm communicator)
    {
      // Each phase's seconds, then the rest of the run.
      const std::array<double, n_phases> phases = seconds();
      std::vector<double>                own(phases.begin(), phases.end());
      double                             charged = 0;
      for (const double s : phases)
        charged += s;
      own.push_back(total_seconds - charged);
      const std::vector<Spread> spreads =
        spread_over_processes(own, communicator);
      if (spreads.empty())
        return;

      // The slowest process's rank only where there are several.
      const bool several =
        dealii::Utilities::MPI::n_mpi_processes(communicator) > 1;
      const auto row = [&](const char *label, const Spread &spread) {
        out << "  " << std::left << std::setw(24) << label << std::right
            << std::fixed << std::setprecision(3) << std::setw(10)
            << spread.least << std::setw(10) << spread.most
            << std::setprecision(1) << std::setw(8)
            << (total_seconds > 0 ? 100 * spread.most / total_seconds : 0.)
            << " %" << std::defaultfloat;
        if (several)
          out << std::setw(9) << spread.slowest;
        out << '\n';
      };
      out << "where the time went (wall seconds, least and most over the "
          << dealii::Utilities::MPI::n_mpi_processes(communicator)
          << " process(es), of " << std::fixed << std::setprecision(3)
          << total_seconds << std::defaultfloat << " s):\n"
          << "  " << std::left << std::setw(24) << "phase" << std::right
          << std::setw(10) << "least" << std::setw(10) << "most"
          << std::setw(10) << "share" << (several ? "  slowest" : "") << '\n';
      for (std::size_t p = 0; p < n_phases; ++p)
        if (spreads[p].most >= 5e-4) // not shown as 0.000
          row(name(static_cast<Phase>(p)), spreads[p]);
      row("other", spreads[n_phases]);
      out << std::flush;
    }
  } // namespace phase_times
} // namespace rodnet
