// velocity batch: render a job of many models x many views to a folder, on this machine
// or on a Dask cluster. The job runner is the Python package's (python/velocity/
// batch.py: manifest, atomic writes, resume, progress bar, Dask); this command runs it
// with the interpreter the module was built for, finding the package in the build tree
// or where it was installed.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "velocity/error.hpp"

namespace velocity::cli {

namespace {

#ifdef VELOCITY_PYTHON
// The folder that holds the `velocity` package: the build tree's when this program
// runs from the build tree, else the installed one.
std::string package_parent() {
  for (const char* dir : {VELOCITY_PYTHON_BUILD_DIR, VELOCITY_PYTHON_INSTALL_DIR})
    if (std::filesystem::exists(std::filesystem::path(dir) / "velocity" / "batch.py")) return dir;
  return {};
}
#endif

}  // namespace

std::function<int()> add_batch_command(CLI::App& app) {
  auto args = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand(
      "batch", "Render a job (many models x many views) to a folder, here or on a Dask cluster; "
               "`velocity batch --help` for its options");
  // Everything after `batch` goes to the job runner, --help included.
  cmd->prefix_command();
  cmd->set_help_flag();
  return [cmd, args]() -> int {
#ifdef VELOCITY_PYTHON
    const std::string parent = package_parent();
    if (parent.empty())
      throw Error("batch: the Python package 'velocity' is neither in " VELOCITY_PYTHON_BUILD_DIR " nor in " VELOCITY_PYTHON_INSTALL_DIR);
    const char* old = std::getenv("PYTHONPATH");
    const std::string path = old && *old ? parent + ":" + old : parent;
    setenv("PYTHONPATH", path.c_str(), 1);
    setenv("VELOCITY_BATCH_PROG", "velocity batch", 1);
    std::vector<std::string> words = {VELOCITY_PYTHON, "-m", "velocity.batch"};
    for (const std::string& a : cmd->remaining()) words.push_back(a);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    execv(VELOCITY_PYTHON, argv.data());
    throw Error(std::string("batch: cannot run ") + VELOCITY_PYTHON + ": " + std::strerror(errno));
#else
    throw Error("batch: this build has no Python module (it needs python3-dev, python3-numpy, pybind11-dev and libpng-dev)");
#endif
  };
}

}  // namespace velocity::cli
