// The option-file check that runs before PetscInitialize, and the safe-name rule, on files
// written here: what PETSc 3.18 accepts passes (comments, alias, a quoted value with spaces,
// nested files, YAML), what it stops on with a traceback or what runs a program is refused
// with a line naming the file and line.
#include "slipwave/core/option_files.hpp"
#include "slipwave/core/option_rules.hpp"

#include "unit_check.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

std::string g_dir;

std::string write(const std::string &name, const std::string &text) {
  const std::string path = g_dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

std::string check(const std::string &path) {
  const char *argv[] = {"slipwave", "-skip_petscrc", "-options_file", path.c_str()};
  return slipwave::core::OptionFilesCheck(4, argv);
}

bool contains(const std::string &text, const std::string &part) { return text.find(part) != std::string::npos; }

} // namespace

int main() {
  char dir[] = "/tmp/test_option_files.XXXXXX";
  g_dir      = mkdtemp(dir);

  const std::string inner = write("inner.opts", "-output_fields false\n");
  unit::check(check(write("good.opts", "# scene\n-dry_run  # stop early\nalias -dt -ts_dt\n-dt 1e-3\n-output_dir \"my out\"\n"
                                       "-options_file " + inner + "\n\n"))
                  .empty(),
              "comments, alias, a quoted value with a space and a nested file pass");
  unit::check(check(write("good.yaml", "mesh:\n  box_faces: 4,4\nmaterial_soil_rho: 2000\n")).empty(), "a YAML mapping passes");
  unit::check(contains(check(write("two.opts", "-a 1 2\n")), "two.opts:1: '2' after the value of -a"), "a second value on a line is refused");
  // An option given twice in one file: an error naming both lines (PETSc keeps the last silently).
  unit::check(contains(check(write("twice.yaml", "a: 1\nb: 2\na: 3\n")), "twice.yaml:3: a is given a second time (first at line 1)"), "a YAML key given twice");
  unit::check(contains(check(write("nested.yaml", "material_soil_vs: 1\nmaterial:\n  soil_vs: 2\n")), "nested.yaml:3: material_soil_vs is given a second time (first at line 1)"),
              "a flat and a nested YAML key that flatten alike");
  unit::check(contains(check(write("twice.opts", "-a 1\n# b\n-a 2\n")), "twice.opts:3: a is given a second time (first at line 1)"), "an option given twice in a text file");
  unit::check(check(write("once.yaml", "mesh:\n  box_faces: 4,4\nmesh_box_upper: 1,1\n")).empty(), "distinct flattened keys pass");
  unit::check(contains(check(write("alias.opts", "alias -x\n")), "alias.opts:1: alias needs two names"), "alias with one name is refused");
  unit::check(contains(check(write("word.opts", "\n\nfoo\n")), "word.opts:3: 'foo' is not an option name"), "a line not starting with -name is refused, with its line");
  unit::check(contains(check(write("bang.opts", "! not a comment for PETSc\n")), "bang.opts:1: '!' is not an option name"), "'!' does not start a comment");
  unit::check(contains(check(write("tab.opts", "-a\x01\n")), "not a text file (byte 0x01 at offset 2)"), "a control byte makes it binary");
  unit::check(contains(check(write("dbg.opts", "-debugger_pause 5\n")), "-debugger_pause runs a program"), "any *debugger* option is refused in a file");
  unit::check(contains(check(write("term.opts", "-debug_terminal \"xterm -e\"\n")), "-debug_terminal runs a program"), "-debug_terminal is refused in a file");
  unit::check(contains(check(write("xv.yaml", "x:\n  virtual: true\n")), "xv.yaml:2: -x_virtual runs a program"), "a nested YAML key is flattened as PETSc does");
  unit::check(contains(check(write("log.opts", "-log_view :/etc/x\n")), "log.opts:1: -log_view :/etc/x writes a file"), "-log_view to a file is refused in a file");
  unit::check(contains(check(write("ksp.yaml", "ksp:\n  view: ascii:../../x\n")), "ksp.yaml:2: -ksp_view ascii:../../x writes a file"), "a YAML viewer to a file is refused");
  unit::check(check(write("stdout.opts", "-log_view\n-ksp_view ascii\n-ts_monitor\n-info :vec\n")).empty(), "viewers to standard output pass");
  unit::check(contains(check(write("trace.opts", "-log_trace /tmp/t\n")), "-log_trace /tmp/t writes a file"), "-log_trace FILE is refused in a file");
  unit::check(contains(check(write("bad.yaml", "a: [1,\n")), "not valid YAML"), "broken YAML is refused");
  unit::check(contains(check(g_dir), "is a directory"), "a directory is refused");
  {
    const char *argv[] = {"slipwave", "-skip_petscrc", "-start_in_debugger", "noxterm"};
    unit::check(slipwave::core::OptionFilesCheck(4, argv).empty(), "debugger options on the command line are allowed");
  }
  {
    const char *argv[] = {"slipwave", "-skip_petscrc", "-options_file", "-dry_run"};
    unit::check(contains(slipwave::core::OptionFilesCheck(4, argv), "-options_file needs a file name"), "-options_file followed by an option is refused");
  }

  using slipwave::core::IsSafeFileName;
  unit::check(IsSafeFileName("S1") && IsSafeFileName("base-2.left_v") && IsSafeFileName("a.b"), "letters, digits, '_', '.', '-' are safe");
  unit::check(!IsSafeFileName("") && !IsSafeFileName(".hidden") && !IsSafeFileName("..") && !IsSafeFileName("a..b"), "empty, leading dot and '..' are refused");
  unit::check(!IsSafeFileName("a/b") && !IsSafeFileName("a b") && !IsSafeFileName("a\\b") && !IsSafeFileName("caf\xc3\xa9"), "slash, space, backslash, non-ASCII refused");

  const int removed = std::system(("rm -rf " + g_dir).c_str());
  unit::check(removed == 0, "temporary directory removed");
  return unit::failures();
}
