#pragma once
// The opening lines every case's gnuplot script shares: a comment naming the plot, the PNG terminal
// and file (io/gnuplot.hpp: the `set output` line the driver swaps for its temporary), and CSV input
// whose comment line and column-name header are skipped (the header's first letter joins '#' as a
// comment character).
#include <string>

#include "sphmol/io/gnuplot.hpp"

namespace sphmol {

inline std::string gnuplot_csv_preamble(const std::string& comment, int width, int height, int font_size,
                                        const std::string& png, char header_start) {
  std::string line = comment;
  for (char& c : line)
    if (c == '\n' || c == '\r' || c == '\\') c = ' ';  // a newline or a trailing backslash would leave the comment
  const char header[2] = {header_start, '\0'};
  return "# " + line + "\nset terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font '," + std::to_string(font_size) + "'\n" + gnuplot_output_line(png) +
         "set datafile separator ','\nset datafile commentschars " + gnuplot_text(std::string("#") + header) + "\n";
}

}  // namespace sphmol
