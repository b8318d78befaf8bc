// kolsky: command-line front of the SHPB suite. Subcommands: run, analyze, eos, sweep, defaults.
// Exit codes: 0 ok, 1 usage/internal error, 2 bad input (InputError), 3 numerical failure.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "core/errors.hpp"
#include "core/build_info.hpp"
#include "ensemble/ensemble.hpp"

namespace {

const char* kUsage =
    "kolsky - split Hopkinson pressure bar (Kolsky bar) simulation and analysis\n"
    "\n"
    "usage:\n"
    "  kolsky run SCENE.json [-o OUT.h5] [--gauges-csv G.csv] [--plot DIR] [--threads N]\n"
    "             [--quiet] [--checkpoint-every S [--checkpoint-file CK.h5]] [--restart CK.h5]\n"
    "      run a scene (docs/scene.md); writes HDF5 probes (default: SCENE stem + .h5) and\n"
    "      prints a summary; --gauges-csv also writes the simulated gauge record in the\n"
    "      format `kolsky analyze` reads. --checkpoint-every S saves the complete state every\n"
    "      S simulated seconds to CK.h5 (default OUT stem + .ckpt.h5, replaced each time);\n"
    "      --restart CK.h5 continues from it (same scene; only time.end may differ), bitwise\n"
    "      as the uninterrupted run. Not for specimen.model = fe. DEM scenes with\n"
    "      output.snapshot_interval also write OUT stem + .particles.h5 and .xmf (ParaView).\n"
    "      --plot DIR draws what analyze draws, from the simulated gauges and face waves, plus\n"
    "      one figure per further probe (DEM: coordination, grain kinetic energy, contacts).\n"
    "      --threads N: OpenMP threads at most (default: OMP_NUM_THREADS, else the cores); a\n"
    "      DEM specimen's steps drop to one thread while that is faster (a core busy with\n"
    "      another process) and take N back when it frees up; results do not depend on it\n"
    "  kolsky analyze GAUGES.csv --bars BARS.json [-o OUT.csv] [--plot DIR] [--quiet]\n"
    "                 [--allow-incomplete]\n"
    "      process strain-gauge records (time, incident strain, transmitted strain) into\n"
    "      specimen strain, strain rate, front/back/average stress, alpha(t), wave energies.\n"
    "      --plot DIR writes PNGs there: raw gauges with pulse windows and removed offsets,\n"
    "      face waves, strain rate, stress-strain, alpha(t), energies (scripts in\n"
    "      DIR/plots_src/). Needs gnuplot at run time ($KOLSKY_GNUPLOT, else PATH); without\n"
    "      it --plot stops with exit 2 before any work. A record kolsky run wrote for a run\n"
    "      stopped early (signal, numerical failure) says so in its first line and is refused\n"
    "      (exit 2) unless --allow-incomplete\n"
    "  kolsky eos --water W [--porosity n] [-o eos.csv] [--help for more options]\n"
    "      three-phase soil EOS (Eqs. 2.1-2.9): P(eps_v) and its components P_BC, P_D, P_E;\n"
    "      W in percent of dry mass (docs/eos.md)\n"
    "  kolsky sweep SCENE.json --set KEY=VALUES [--set ...] [--seeds K] [--threads N]\n"
    "               [-o TABLE] [--plot DIR] [--quiet]\n"
    "      run the scene once per member of the product of every KEY's values and the packing\n"
    "      seeds (--seeds K: specimen.seed = 1..K). VALUES: a JSON list [a,b,...], lo:hi:count\n"
    "      (evenly spaced, ends included), log:lo:hi:count (evenly in log), or one JSON value.\n"
    "      Writes one row per member (the values, seed, run summary figures, steps, run time,\n"
    "      status, error) to TABLE.csv and TABLE.h5 (default: SCENE stem + _sweep); finished\n"
    "      members are cached in TABLE.cache/ and a rerun skips them. --threads N: members at\n"
    "      once (default 1); under `mpirun -n K kolsky sweep ...` the members spread over the\n"
    "      ranks. --plot DIR: each summary figure against the first KEY, seeds as scatter with\n"
    "      mean +- sd. Every member's scene is checked first (exit 2); a failed member is a\n"
    "      row, and the exit code is 3 when one failed numerically (docs/scene.md)\n"
    "  kolsky defaults\n"
    "      every scene and BARS.json parameter with its default, unit and description\n"
    "  kolsky --help | --version\n"
    "\n"
    "exit codes: 0 ok, 1 usage error (or an output that could not be written), 2 bad input,\n"
    "3 numerical failure (output kept, marked incomplete), 130/143 stopped by SIGINT/SIGTERM\n"
    "(run: at the next step, output kept, marked incomplete)\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 1 : 0;
  }
  if (args[0] == "--version") {
    std::printf("kolsky %s (%s, %s)\n", kolsky::build_info::version(), kolsky::build_info::git_commit(), kolsky::build_info::build_type());
    return 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  // `kolsky run --help` and the like: the one usage text (eos has its own longer --help).
  const bool wants_help = std::find_if(args.begin(), args.end(), [](const std::string& a) {
                            return a == "--help" || a == "-h";
                          }) != args.end();
  if (wants_help && (cmd == "run" || cmd == "analyze" || cmd == "sweep" || cmd == "defaults")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  // Under mpirun a sweep spreads its members over the ranks; started alone, nothing of MPI runs.
  std::optional<kolsky::ensemble::MpiSession> mpi;
  if (cmd == "sweep") mpi.emplace(&argc, &argv);
  try {
    if (cmd == "run") return kolsky::app::cmd_run(args);
    if (cmd == "sweep") return kolsky::app::cmd_sweep(args);
    if (cmd == "analyze") return kolsky::app::cmd_analyze(args);
    if (cmd == "defaults") return kolsky::app::cmd_defaults(args);
    if (cmd == "eos") return kolsky::app::cmd_eos(args);
    std::fprintf(stderr, "kolsky: unknown command '%s' (run, analyze, eos, sweep, defaults; see --help)\n",
                 cmd.c_str());
    return 1;
  } catch (const kolsky::app::UsageError& e) {
    std::fprintf(stderr, "kolsky %s: %s (see kolsky --help)\n", cmd.c_str(), e.what());
    return 1;
  } catch (const kolsky::InputError& e) {
    std::fprintf(stderr, "kolsky: error: %s\n", e.what());
    return kolsky::kExitInputError;
  } catch (const kolsky::StopRequested& e) {  // a signal before the run had anything to keep
    std::fprintf(stderr, "kolsky %s: %s: %s\n", cmd.c_str(), kolsky::app::interrupt_name(), e.what());
    return 128 + kolsky::app::interrupt_signal();
  } catch (const kolsky::NumericalError& e) {
    std::fprintf(stderr, "kolsky: numerical failure: %s\n", e.what());
    return kolsky::kExitNumericalError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kolsky: internal error: %s\n", e.what());
    return 1;
  }
}
