#pragma once
// The opening lines every case's gnuplot script shares: a comment naming the plot, the PNG terminal
// and file, and CSV input whose comment line and column-name header are skipped (the header's first
// letter joins '#' as a comment character).
#include <string>

namespace sphmol {

inline std::string gnuplot_csv_preamble(const std::string& comment, int width, int height, int font_size,
                                        const std::string& png, char header_start) {
  return "# " + comment + "\nset terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font '," + std::to_string(font_size) + "'\nset output '" + png +
         "'\nset datafile separator ','\nset datafile commentschars '#" + std::string(1, header_start) + "'\n";
}

}  // namespace sphmol
