#include "slipwave/app/output_dir.hpp"

#include "slipwave/app/checkpoint.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace slipwave::app {
namespace fs = std::filesystem;
namespace {

// Longest folder path accepted, absolute: the HDF5 files are opened through Open MPI's MPI-IO,
// whose shared-file-pointer component writes the file's path and a suffix ("_cid-<c>-<r>.sm",
// 12 to about 20 characters) into a 256-byte buffer and aborts the run past it (measured with
// Open MPI 4.1: volume/.000000.h5.partial under a 218-character folder runs, under 219 it
// aborts with "buffer overflow detected"). 180 leaves about 55 characters for the longest name
// inside ("interface_<name>/.<step>.h5.partial" with a name of up to ~20 characters).
constexpr size_t kMaxDirLength = 180;

// True for a name slipwave writes into the output folder (see the writers: energy_csv.cpp,
// run_report.cpp, input_motion_csv.cpp, checkpoint.cpp, stations.cpp, field_writer.cpp, rigid_histories.cpp).
bool isRunFile(const std::string &name) {
  static const char *const exact[] = {"energy.csv", "run_info.json", "input_motion.csv", "checkpoint.bin", "checkpoint.bin.tmp", "volume.h5", "volume.xmf", "volume",
                                      ".volume.h5.partial", ".volume.xmf.partial", "stations.h5", ".stations.h5.spare", ".stations.h5.partial", "stations"};
  for (const char *e : exact)
    if (name == e) return true;
  auto ends = [&](const char *tail) { const std::string t = tail; return name.size() > t.size() && name.compare(name.size() - t.size(), t.size(), t) == 0; };
  // interface_<name>.h5/.xmf, its frame folder interface_<name> and their partial names.
  const bool frames = name.find('.') == std::string::npos;
  // rigid_<region>.csv: the rigid bodies' histories (rigid_histories.cpp).
  if (name.rfind("rigid_", 0) == 0 && ends(".csv")) return true;
  return (name.rfind("interface_", 0) == 0 && (ends(".h5") || ends(".xmf") || frames)) ||
         (name.rfind(".interface_", 0) == 0 && (ends(".xmf.partial") || ends(".h5.partial")));
}

// The value as shown in a message: a very long one is cut, with its length.
std::string shown(const std::string &dir) {
  if (dir.size() <= 80) return dir;
  return dir.substr(0, 60) + "... (" + std::to_string(dir.size()) + " characters)";
}

// The same folder (both exist)?
bool sameFolder(const fs::path &a, const fs::path &b) {
  std::error_code error;
  return fs::equivalent(a, b, error) && !error;
}

// The nearest existing ancestor of path (or path itself), for a dry run's write check.
fs::path existingAncestor(fs::path path) {
  std::error_code error;
  path = fs::absolute(path, error);
  while (!path.empty() && !fs::exists(path, error) && path.has_parent_path() && path.parent_path() != path) path = path.parent_path();
  return path;
}

// Rank 0's whole check; returns the message after "-output_dir = <dir>: ", or "" when all is well.
std::string check(const OutputDirRequest &q) {
  const std::string &dir = q.dir;
  if (dir.empty()) return "the folder name is empty; allowed: a folder path (created if missing)";
  std::error_code absolute_error;
  const size_t    length = fs::absolute(dir, absolute_error).string().size();
  if (length > kMaxDirLength)
    return "the path is too long (" + std::to_string(length) + " characters from the root); allowed: at most " + std::to_string(kMaxDirLength) +
           " (Open MPI's file writing aborts on longer paths)";
  std::error_code error;
  const fs::file_status status = fs::status(dir, error);
  if (fs::exists(status) && !fs::is_directory(status)) return "it exists and is not a folder; allowed: a folder path (created if missing)";
  if (!q.create) {
    const fs::path base = existingAncestor(dir);
    if (!fs::is_directory(base, error)) return "'" + shown(base.string()) + "' is not a folder; allowed: a folder path (created if missing)";
    if (access(base.c_str(), W_OK | X_OK) != 0) return "cannot write in '" + shown(base.string()) + "' (" + std::strerror(errno) + "); allowed: a writable folder";
  } else {
    fs::create_directories(dir, error);
    if (error) return "cannot create the folder (" + error.message() + "); allowed: a writable folder path";
    // Permissions alone do not tell (root, read-only mounts, quotas): write a file and remove it.
    const std::string probe = dir + "/.slipwave_write_probe";
    FILE             *fp    = std::fopen(probe.c_str(), "w");
    const int         code  = fp ? 0 : errno;
    if (fp) std::fclose(fp);
    std::remove(probe.c_str());
    if (!fp) return std::string("cannot write in the folder (") + std::strerror(code) + "); allowed: a writable folder";
  }
  const std::vector<std::string> old = OutputDirRunFiles(dir);
  if (old.empty()) return "";
  // A restart continues the series of the folder that holds its checkpoint.
  if (!q.restart.empty() && sameFolder(CheckpointFolder(q.restart), dir)) return "";
  if (!q.overwrite) {
    std::string listed;
    for (size_t k = 0; k < old.size() && k < 4; ++k) listed += (k ? ", " : "") + old[k];
    if (old.size() > 4) listed += ", ...";
    return "holds the output of an earlier run (" + listed + "); allowed: a new or empty folder, or -output_overwrite to delete those files first";
  }
  if (!q.create) return "";
  for (const std::string &name : old) {
    fs::remove_all(fs::path(dir) / name, error);
    if (error) return "cannot delete the earlier run's " + name + " (" + error.message() + "); allowed: a writable folder";
  }
  return "";
}

} // namespace

std::vector<std::string> OutputDirRunFiles(const std::string &dir) {
  std::vector<std::string> found;
  std::error_code          error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
    if (isRunFile(it->path().filename().string())) found.push_back(it->path().filename().string());
  std::sort(found.begin(), found.end());
  return found;
}

PetscErrorCode OutputDirPrepare(MPI_Comm comm, const OutputDirRequest &request) {
  PetscMPIInt rank;
  char        message[1024] = "";
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::string text;
    PetscCallCXX(text = check(request));
    if (!text.empty()) std::snprintf(message, sizeof message, "-output_dir = %s: %s", shown(request.dir).c_str(), text.c_str());
  }
  PetscCallMPI(MPI_Bcast(message, sizeof message, MPI_CHAR, 0, comm));
  PetscCheck(!message[0], comm, PETSC_ERR_USER_INPUT, "%s", message);
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
