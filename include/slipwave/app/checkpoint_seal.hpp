// A checkpoint's seal: a trailer appended after the data (magic, length of the data, FNV-1a
// checksum of the data). A file cut short (a full disk, a kill during a copy) or damaged is
// then recognized before PETSc reads a byte of it, and refused in one line, instead of failing
// deep in a vector load with a traceback.
#pragma once
#include <string>

namespace slipwave::app {

// Appends the seal to the finished file; false (with errno set) if it cannot.
bool CheckpointSeal(const std::string &path);
// "" if the file carries an intact seal, else what is wrong with it.
std::string CheckpointSealProblem(const std::string &path);

} // namespace slipwave::app
