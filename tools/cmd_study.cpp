// hinge study [--quick] [--out DIR] [--input HINGES.jsonl] [--sample N] [--methods LIST] [--scalars LIST]
//             [--plugin LIB.so [--symbol NAME] [--name LABEL]]... [--budget S] [--no-mesh] [--no-plots]
//             (docs/contract.md; docs/study.md)
// Runs hinge::study, writes DIR/study.json and DIR/study.md (whole or not at all), renders the plots with
// the committed script plot_study.py when Python and matplotlib are there, prints the summary.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "hinge/conformance/plugin.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/io/study_json.hpp"
#include "hinge/study/study.hpp"
#include "progress.hpp"

namespace hinge::tools {

namespace {

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

// plot_study.py: beside the executable in a build tree, in ../share/hinge once installed.
std::optional<std::filesystem::path> plot_script() {
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  for (const auto& candidate :
       {exe.parent_path() / "plot_study.py", exe.parent_path() / ".." / "share" / "hinge" / "plot_study.py"})
    if (std::filesystem::exists(candidate)) return candidate;
  return std::nullopt;
}

// Quotes a path for the shell.
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Renders DIR/pareto, histogram, scaling (.svg, .png) from DIR/study.json; says why when it cannot.
void render_plots(const std::filesystem::path& dir) {
  const auto script = plot_script();
  const char* python = ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  if (!script) {
    std::cerr << "hinge study: plots not written: plot_study.py is not installed beside the program\n";
    return;
  }
  const std::string command = std::string(python) + " " + quoted(script->string()) + " " +
                              quoted((dir / "study.json").string()) + " " + quoted(dir.string());
  if (std::system(command.c_str()) != 0)
    std::cerr << "hinge study: plots not written (" << command << " failed; it needs python3-matplotlib)\n";
}

}  // namespace

int run_study(const study::Options& given, const std::string& out, bool plots) {
  study::Options options = given;
  std::optional<Progress> certifying;
  options.progress = [&certifying](const std::string& stage, std::size_t done, std::size_t total) {
    if (stage == "certifying") {
      if (!certifying) certifying.emplace("hinge study: certifying the hinges", total);
      certifying->update(done);
      if (done == total) certifying.reset();
    } else if (done < total) {
      std::cerr << "hinge study: [" << done + 1 << "/" << total << "] " << stage << std::endl;
    }
  };
  try {
    const study::Study result = study::run(options);
    const std::filesystem::path dir(out);
    std::filesystem::create_directories(dir);
    {
      io::AtomicFile json((dir / "study.json").string()), markdown((dir / "study.md").string());
      io::write_study_json(json.stream(), result);
      study::write_markdown(markdown.stream(), result);
      json.commit();
      markdown.commit();
    }
    if (plots) render_plots(dir);
    study::print_summary(std::cout, result);
    std::cout << "written: " << (dir / "study.json").string() << ", " << (dir / "study.md").string()
              << (plots ? ", pareto/histogram/scaling .svg .png" : "") << std::endl;
    return exit_done;
  } catch (const InputError& e) {
    std::cerr << "hinge study: " << e.what() << "\n";
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "hinge study: " << e.what() << "\n";
  } catch (const std::runtime_error& e) {  // io::AtomicFile: a file that could not be written
    std::cerr << "hinge study: " << e.what() << "\n";
  }
  return exit_invalid_input;
}

Action add_study(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "study", "What accuracy costs in time: every method in every scalar type, against the certified oracle");
  struct Options {
    bool quick = false, no_mesh = false, no_plots = false;
    std::string out = "study", input, methods, scalars;
    std::vector<std::string> plugins, symbols, names;
    std::size_t sample = 0;
    double budget = 0;
  };
  auto o = std::make_shared<Options>();
  cmd->add_flag("--quick", o->quick, "The quick study (about a minute): fewer sizes, shorter budgets");
  cmd->add_option("--out", o->out, "Output folder: study.json, study.md, pareto/histogram/scaling .svg and .png")
      ->capture_default_str();
  cmd->add_option("--input", o->input,
                  "Study these hinges (hinge eval's input format; a line's \"category\" groups it)");
  cmd->add_option("--sample", o->sample, "Study N of the input hinges, drawn reproducibly")->check(CLI::PositiveNumber);
  cmd->add_option("--methods", o->methods,
                  "Comma-separated methods (default: reference,fast,autodiff,symbolic,faithful,oracle)");
  cmd->add_option("--plugin", o->plugins,
                  "An outside implementation (hinge/candidate.h) as a row, timed in its own process; repeatable");
  cmd->add_option("--symbol", o->symbols,
                  "The i-th --plugin's function (default hinge_candidate); repeatable, in the plugins' order");
  cmd->add_option("--name", o->names, "The i-th --plugin's row label (default its file name); repeatable");
  cmd->add_option(
      "--scalars", o->scalars,
      "Comma-separated scalar types (default: float,double,long-double,dd,qd,float128,bin128,mpfr:128,mpfr:256)");
  cmd->add_option("--budget", o->budget, "Seconds per row and per mesh row (default: 1.5 quick, 20 full)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--no-mesh", o->no_mesh, "Skip the mesh level");
  cmd->add_flag("--no-plots", o->no_plots, "Do not render the plots");
  cmd->footer("Exit: 0 done; 1 invalid input file (message names the file and line; nothing written); 2 usage error.");
  return [o]() -> int {
    study::Options options;
    options.quick = o->quick;
    options.mesh = !o->no_mesh;
    options.budget_seconds = o->budget;
    for (const auto& m : split(o->methods))
      options.methods.push_back(study::check_method(m));  // invalid_argument: usage
    if (o->symbols.size() > o->plugins.size() || o->names.size() > o->plugins.size())
      throw std::invalid_argument("the i-th --symbol and --name belong to the i-th --plugin: more given than plugins");
    for (std::size_t i = 0; i < o->plugins.size(); ++i) {
      try {
        options.outside.push_back(study::plugin_candidate(o->plugins[i],
                                                          i < o->symbols.size() ? o->symbols[i] : "hinge_candidate",
                                                          i < o->names.size() ? o->names[i] : ""));
      } catch (const conformance::PluginError& e) {
        std::cerr << "hinge study: " << e.what() << "\n";
        return exit_usage;
      }
    }
    for (const auto& s : split(o->scalars)) options.scalars.push_back(parse_scalar_type(s));
    if (!o->input.empty()) {
      try {
        options.hinges = study::sample(study::read_hinges(o->input), o->sample);
      } catch (const InputError& e) {
        std::cerr << "hinge study: " << e.what() << "\n";
        return exit_invalid_input;
      }
      options.source = o->input;
    } else if (o->sample) {
      throw std::invalid_argument("--sample needs --input");
    }
    return run_study(options, o->out, !o->no_plots);
  };
}

}  // namespace hinge::tools
