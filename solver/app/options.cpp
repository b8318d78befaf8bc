#include <algorithm>
#include <string>

#include "app/commands.hpp"
#include "scene/scene.hpp"

namespace kolsky::app {

namespace {

int whole_number(const std::string& option, const std::string& v) {
  try {
    size_t used = 0;
    const int n = std::stoi(v, &used);
    if (used != v.size() || n < 1) throw std::invalid_argument(v);
    return n;
  } catch (const std::exception&) {
    throw UsageError(option + " needs a whole number >= 1, got '" + v + "'");
  }
}

}  // namespace

Options parse_options(const std::vector<std::string>& args, const std::vector<std::string>& allowed) {
  Options o;
  auto takes = [&](const std::string& a) {
    return std::find(allowed.begin(), allowed.end(), a) != allowed.end();
  };
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 1 && a[0] == '-') {
      if (!takes(a)) throw UsageError("unknown option '" + a + "'");
      if (a == "--quiet") { o.quiet = true; continue; }
      if (a == "--allow-incomplete") { o.allow_incomplete = true; continue; }
      if (i + 1 >= args.size()) throw UsageError("option '" + a + "' needs a value");
      const std::string& v = args[++i];
      if (a == "-o") o.output = v;
      else if (a == "--bars") o.bars = v;
      else if (a == "--gauges-csv") o.gauges_csv = v;
      else if (a == "--checkpoint-file") o.checkpoint_file = v;
      else if (a == "--restart") o.restart = v;
      else if (a == "--plot") o.plot_dir = v;
      else if (a == "--checkpoint-every") {
        try {
          size_t used = 0;
          o.checkpoint_every = std::stod(v, &used);
          if (used != v.size() || !(o.checkpoint_every > 0)) throw std::invalid_argument(v);
        } catch (const std::exception&) {
          throw UsageError("--checkpoint-every needs a time in s > 0, got '" + v + "'");
        }
      }
      else if (a == "--set") o.sets.push_back(v);
      else if (a == "--threads") o.threads = whole_number(a, v);
      else if (a == "--seeds") o.seeds = whole_number(a, v);
      continue;
    }
    o.positional.push_back(a);
  }
  return o;
}

int cmd_defaults(const std::vector<std::string>& args) {
  if (!args.empty()) throw UsageError("takes no arguments");
  std::fputs(scene::format_defaults().c_str(), stdout);
  return 0;
}

}  // namespace kolsky::app
