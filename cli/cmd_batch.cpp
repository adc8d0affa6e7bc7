// fgsg batch JOBS.json: the Python package's Dask batch runner (python/fgsg/batch.py),
// run with the python3 the package was built for and the package of this build or
// installation on its path: `python3 -m fgsg.batch` by another name. Its main is called
// from the imported module (not run as __main__), so that the tasks it sends a cluster
// are fgsg.batch's functions, which the workers import.
#include "cli/commands.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace fgsg::cli {

namespace fs = std::filesystem;

int batchCommand(const Args& args) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::string package;  // the folder holding fgsg/ (build: build/python; installed: lib/python3/dist-packages)
  for (const fs::path& dir : {exe.parent_path().parent_path() / "python",
                              exe.parent_path().parent_path() / "lib" / "python3" / "dist-packages"})
    if (fs::is_regular_file(dir / "fgsg" / "batch.py", ec)) {
      package = dir.string();
      break;
    }
  if (package.empty()) {
    std::cerr << "fgsg batch: the Python package fgsg is not beside this fgsg (build/python, or "
                 "lib/python3/dist-packages when installed): build it with the rest\n";
    return 1;
  }
  const char* old = std::getenv("PYTHONPATH");
  const std::string path = package + (old && *old ? ":" + std::string(old) : "");
  setenv("PYTHONPATH", path.c_str(), 1);
  setenv("FGSG_BATCH_PROG", "fgsg batch", 1);  // its usage line names this command
  std::vector<std::string> words = {FGSG_PYTHON_EXECUTABLE, "-c",
                                    "import sys; from fgsg.batch import main; sys.exit(main())"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::cerr << "fgsg batch: cannot run " << words[0] << ": " << std::strerror(errno) << "\n";
  return 1;
}

}  // namespace fgsg::cli
