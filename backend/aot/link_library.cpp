#include "backend/aot/link_library.h"

#include "runtime/io/output_transaction.h"
#include "runtime/io/temp_cleanup.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace fgsg::backend::aot {

namespace {

namespace fs = std::filesystem;

std::string errnoText(int e) { return std::strerror(e); }

// Removes a file when it goes out of scope (unless released), and on SIGINT/SIGTERM
// while it exists.
struct TempFile {
  std::string path;
  int cleanupSlot = -1;
  void track(std::string p) {
    path = std::move(p);
    cleanupSlot = rt::io::registerTempForCleanup(path.c_str());
  }
  ~TempFile() {
    if (!path.empty()) ::unlink(path.c_str());
    rt::io::releaseTempCleanup(cleanupSlot);
  }
};

bool writeAll(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

std::vector<std::string> compilerCommand() {
  std::vector<std::string> words;
  const char* env = std::getenv("FGSG_CC");
  std::istringstream in(env && *env ? env : "cc");
  for (std::string w; in >> w;) words.push_back(w);
  if (words.empty()) words.push_back("cc");
  return words;
}

// Runs argv (looked up in PATH), stdin from /dev/null, stdout and stderr together into
// `output`. Returns the exit status, or -1 with `error` set when it could not run.
int runProgram(const std::vector<std::string>& args, std::string& output, std::string& error) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    error = "cannot create a pipe: " + errnoText(errno);
    return -1;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (rc != 0) {
    ::close(fds[0]);
    error = "cannot run the C compiler '" + args[0] + "' (set FGSG_CC to another): " + errnoText(rc);
    return -1;
  }
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    output.append(buf, static_cast<size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      error = "waiting for '" + args[0] + "': " + errnoText(errno);
      return -1;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  error = "'" + args[0] + "' was killed by signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return -1;
}

}  // namespace

bool linkSharedLibrary(const std::string& object, const std::string& outputPath,
                       const std::string& libDir, std::string& error) {
  std::error_code ec;
  const fs::path out(outputPath);
  const fs::path outDir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  if (!fs::is_directory(outDir, ec)) {
    error = "cannot write " + outputPath + ": the folder " + outDir.string() + " does not exist";
    return false;
  }

  // The object, in the temporary folder.
  const char* tmpEnv = std::getenv("TMPDIR");
  std::string objTemplate = std::string(tmpEnv && *tmpEnv ? tmpEnv : "/tmp") + "/fgsg-object-XXXXXX.o";
  std::vector<char> objName(objTemplate.begin(), objTemplate.end());
  objName.push_back('\0');
  const int objFd = ::mkstemps(objName.data(), 2);
  if (objFd < 0) {
    error = "cannot create a temporary file " + objTemplate + ": " + errnoText(errno);
    return false;
  }
  TempFile objFile;
  objFile.track(objName.data());
  const bool written = writeAll(objFd, object);
  const int writeErrno = errno;
  ::close(objFd);
  if (!written) {
    error = "cannot write " + objFile.path + ": " + errnoText(writeErrno);
    return false;
  }

  // The library, beside its final name: rename is atomic only within one file system.
  // The name is reserved with O_EXCL and then left to the linker to replace.
  TempFile libFile;
  {
    std::string name;
    const int fd = rt::io::createUniqueFile((outDir / ("." + out.filename().string() + ".tmp-")).string(), name);
    if (fd < 0) {
      error = "cannot write in " + outDir.string() + ": " + errnoText(errno);
      return false;
    }
    ::close(fd);
    libFile.track(name);
  }

  std::vector<std::string> args = compilerCommand();
  const std::string compiler = args[0];
  for (const std::string& a : {std::string("-shared"), std::string("-o"), libFile.path, objFile.path})
    args.push_back(a);
  if (!libDir.empty())
    for (const std::string& a : {"-L" + libDir, std::string("-lfgsg"), std::string("-Xlinker"), std::string("-rpath"),
                                 std::string("-Xlinker"), libDir})
      args.push_back(a);
  args.push_back("-lm");
  std::string output;
  const int status = runProgram(args, output, error);
  if (status < 0) return false;
  if (status != 0) {
    while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
    error = "linking " + outputPath + " failed (" + compiler + " exited with status " +
            std::to_string(status) + ")" + (output.empty() ? "" : ":\n" + output);
    return false;
  }
  // The library reaches the disk before its name does.
  const int fd = ::open(libFile.path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
  if (::rename(libFile.path.c_str(), outputPath.c_str()) != 0) {
    error = "cannot write " + outputPath + ": " + errnoText(errno);
    return false;
  }
  libFile.path.clear();  // renamed: nothing to remove
  return true;
}

}  // namespace fgsg::backend::aot
