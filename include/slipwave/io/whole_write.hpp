// Output that a kill cannot tear: the text of one flush (station rows, energy.csv rows) is
// handed to the kernel by one write(2), so a run stopped by SIGKILL leaves the file ending
// before or after the whole text, never inside a row. stdio would split a flush of tens of kB
// into several writes (its buffer is 4-8 kB), and a kill between them tears the last row.
#pragma once
#include <string>

namespace slipwave::io {

// Writes all of text to the open descriptor fd (looping only on a short write); false on an
// error (errno says which).
bool WriteWhole(int fd, const std::string &text);

// Appends text to the file at path (created with mode 0644 if missing; emptied first when
// truncate) by WriteWhole; false on an error (errno says which).
bool AppendWhole(const std::string &path, const std::string &text, bool truncate);

} // namespace slipwave::io
