// Jump histories for driving one interface pair: a CSV with the header t,w_T,w_N (2D) or
// t,w_T1,w_T2,w_N (3D), columns in any order, one row per step, '#' lines are comments.
#pragma once

#include <petscsys.h>

#include <istream>
#include <string>
#include <vector>

namespace slipwave::io {

struct JumpHistory {
  int dim = 0;                   // 2 or 3
  std::vector<double> t;         // strictly increasing
  std::vector<double> w;         // per row: dim - 1 tangential components, then w_N
  std::vector<int> line;         // file line of each row, for messages
  std::size_t rows() const { return t.size(); }
};

// Parses the CSV; on failure returns "<source>:<line>: <what is wrong>" and leaves history
// unspecified, on success returns "".
std::string parseJumpHistory(std::istream &in, const std::string &source, JumpHistory &history);

// Reads the file at path; a bad file stops with a user-input error carrying the line number.
PetscErrorCode JumpHistoryCsvRead(MPI_Comm comm, const char *path, JumpHistory *history);

} // namespace slipwave::io
