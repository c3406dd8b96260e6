#pragma once
// The one way sph-mol runs gnuplot (run plots and study charts alike). gnuplot executes a file name
// that starts with '|' or '<' as a shell pipe and ends a command at a newline, so:
//   - gnuplot is started with fork/exec (no shell), from an absolute PATH entry, with the output
//     directory as its working directory and only relative file names that the program generates
//     (plain_file_name); user text never enters a script except through gnuplot_text, which keeps a
//     safe character set;
//   - its standard error goes to <stem>.gnuplot.log in the output directory, a file the program
//     creates itself (O_EXCL temporary, renamed);
//   - the PNG is drawn into a temporary name and renamed to its final name only when gnuplot exited
//     with status 0 and the file is a complete PNG (signature and IEND chunk), so a full disk or a
//     killed gnuplot never leaves a truncated PNG under the final name;
//   - while gnuplot runs, `interrupted` is polled (every 10 ms): when it turns true the child is
//     terminated and the plot reported as interrupted, so a SIGINT/SIGTERM is never held up by it.
#include <functional>
#include <string>
#include <string_view>

namespace sphmol {

// True for a name of [A-Za-z0-9_.+-] that starts with a letter or digit and holds no "..": safe as
// a relative file name and inside a gnuplot single-quoted string.
bool plain_file_name(std::string_view name);

// `name` as a gnuplot single-quoted string; throws std::logic_error unless plain_file_name(name).
std::string gnuplot_file(std::string_view name);

// `text` as a gnuplot single-quoted string for titles and labels: every character outside letters,
// digits, space and _.,:;=+-*/()[]{}^%# is replaced by '_' (a quote would end the string, a newline
// the command; a backquote, '$', '@' or '|' could reach a shell or a macro).
std::string gnuplot_text(std::string_view text);

// The `set output` line a plot script names its PNG with (exactly once); the driver swaps it for the
// temporary name while gnuplot runs.
std::string gnuplot_output_line(std::string_view png);

// Absolute path of gnuplot on PATH (relative PATH entries are skipped: they would run a program from
// the current directory), or "".
std::string find_gnuplot();

struct GnuplotOutcome {
  bool ok = false;
  bool interrupted = false;  // stopped because `interrupted` turned true
  std::string problem;       // why no PNG was made (empty when ok)
};

// Writes `script` to DIR/SCRIPT_NAME (kept so the plot can be redrawn by hand: `cd DIR; gnuplot
// SCRIPT_NAME`) and runs it with gnuplot (GNUPLOT: from find_gnuplot) in DIR to make DIR/PNG.
// The script must contain gnuplot_output_line(png) exactly once; SCRIPT_NAME and PNG must be plain
// file names (std::logic_error otherwise: those are the program's own).
GnuplotOutcome run_gnuplot(const std::string& gnuplot, const std::string& dir, const std::string& script_name,
                           const std::string& script, const std::string& png,
                           const std::function<bool()>& interrupted = {});

}  // namespace sphmol
