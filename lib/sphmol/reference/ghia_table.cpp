#include "sphmol/reference/ghia_table.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sphmol {
namespace {

struct Column {
  std::vector<double> coord, value;
};

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw std::runtime_error("load_ghia: " + path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
}

std::vector<std::string> split_csv(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r"), e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
  }
  if (!s.empty() && s.back() == ',') out.emplace_back();
  return out;
}

double parse_number(const std::string& cell, const std::string& path, int line) {
  char* end = nullptr;
  const double x = std::strtod(cell.c_str(), &end);
  if (cell.empty() || end != cell.c_str() + cell.size() || !std::isfinite(x))
    fail(path, line, "not a number: '" + cell + "'");
  return x;
}

// Reads one table; returns the column for Re (coordinate name cname, value prefix vname + "_Re"), or
// nullopt if the header has no such column.
std::optional<Column> read_table(const std::string& path, const std::string& cname, const std::string& vname, double Re) {
  std::ifstream in(path);
  if (!in) fail(path, 0, "cannot open file");
  std::string text;
  int line_no = 0, col = -1;
  std::size_t ncols = 0;
  bool have_header = false;
  Column c;
  while (std::getline(in, text)) {
    ++line_no;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.empty() || text[0] == '#') continue;
    auto cells = split_csv(text);
    if (!have_header) {
      // Column names may carry their unit, which must be "[-]" (the values are scaled by L and U).
      for (auto& cell : cells) {
        const auto open = cell.find('[');
        if (open == std::string::npos) continue;
        if (cell.substr(open) != "[-]")
          fail(path, line_no, "column '" + cell + "': the table is dimensionless, the unit must be [-]");
        cell.erase(open);
        while (!cell.empty() && cell.back() == ' ') cell.pop_back();
      }
      if (cells.size() < 2 || cells[0] != cname) fail(path, line_no, "header must start with '" + cname + "' and a data column");
      const std::string prefix = vname + "_Re";
      for (std::size_t i = 1; i < cells.size(); ++i) {
        if (cells[i].rfind(prefix, 0) != 0) fail(path, line_no, "column '" + cells[i] + "' is not of the form " + prefix + "<number>");
        const double re = parse_number(cells[i].substr(prefix.size()), path, line_no);
        if (std::abs(re - Re) <= 1e-9 * std::abs(Re)) col = static_cast<int>(i);
      }
      ncols = cells.size();
      have_header = true;
      continue;
    }
    if (cells.size() != ncols)
      fail(path, line_no, "expected " + std::to_string(ncols) + " columns, found " + std::to_string(cells.size()));
    std::vector<double> row;
    for (const auto& cell : cells) row.push_back(parse_number(cell, path, line_no));
    if (row[0] < 0.0 || row[0] > 1.0) fail(path, line_no, cname + " outside [0, 1]");
    if (!c.coord.empty() && !(row[0] > c.coord.back())) fail(path, line_no, cname + " not strictly increasing");
    if (col > 0) {
      c.coord.push_back(row[0]);
      c.value.push_back(row[static_cast<std::size_t>(col)]);
    } else {
      c.coord.push_back(row[0]);  // keep for the monotonicity check only
    }
  }
  if (!have_header) fail(path, 0, "no header line");
  if (c.coord.empty()) fail(path, 0, "no data rows");
  if (col < 0) return std::nullopt;
  return c;
}

}  // namespace

std::optional<GhiaTable> load_ghia(const std::string& path_u, const std::string& path_v, double Re) {
  if (!(Re > 0.0)) throw std::invalid_argument("load_ghia: Re must be positive");
  const auto cu = read_table(path_u, "y", "u", Re);
  const auto cv = read_table(path_v, "x", "v", Re);
  if (!cu && !cv) return std::nullopt;
  if (!cu || !cv)
    throw std::runtime_error("load_ghia: Re = " + std::to_string(Re) + " present in only one of " + path_u + ", " + path_v);
  GhiaTable t;
  t.Re = Re;
  t.y = cu->coord;
  t.u = cu->value;
  t.x = cv->coord;
  t.v = cv->value;
  return t;
}

}  // namespace sphmol
