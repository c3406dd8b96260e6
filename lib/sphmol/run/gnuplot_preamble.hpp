#pragma once
// The opening lines every case's gnuplot script shares: a comment naming the plot, the PNG terminal
// and file, and CSV input whose first row is the column-name header (the CSV files have that row
// and no other non-data line).
#include <string>

namespace sphmol {

inline std::string gnuplot_csv_preamble(const std::string& comment, int width, int height, int font_size,
                                        const std::string& png) {
  return "# " + comment + "\nset terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font '," + std::to_string(font_size) + "'\nset output '" + png +
         "'\nset datafile separator ','\nset datafile columnheaders\n";
}

}  // namespace sphmol
