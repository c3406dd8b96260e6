#pragma once
// The opening lines every case's gnuplot script shares: a comment naming the plot, the PNG terminal
// and file (io/gnuplot.hpp: the `set output` line the driver swaps for its temporary), and CSV input
// whose first row is the column-name header (the CSV files have that row and no other non-data line).
#include <string>

#include "sphmol/io/gnuplot.hpp"

namespace sphmol {

inline std::string gnuplot_csv_preamble(const std::string& comment, int width, int height, int font_size,
                                        const std::string& png) {
  std::string line = comment;
  for (char& c : line)
    if (c == '\n' || c == '\r' || c == '\\') c = ' ';  // a newline or a trailing backslash would leave the comment
  return "# " + line + "\nset terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font '," + std::to_string(font_size) + "'\n" + gnuplot_output_line(png) +
         "set datafile separator ','\nset datafile columnheaders\n";
}

}  // namespace sphmol
