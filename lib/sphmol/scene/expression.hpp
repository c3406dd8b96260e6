#pragma once
// A small arithmetic expression of the coordinates, for initial fields given in the config (e.g. a
// velocity "sin(2*pi*y)"): numbers, x y z, pi, + - * / ^ (right-associative, above unary minus, so
// -x^2 = -(x^2)), parentheses, and the functions sin cos tan exp sqrt abs. Parsed once into a tree and
// evaluated per particle; nothing is handed to another program.
#include <array>
#include <memory>
#include <stdexcept>
#include <string>

namespace sphmol {

// A parse error: `column` is the 1-based position in the text of the offending character.
struct ExpressionError : std::runtime_error {
  ExpressionError(std::size_t column, const std::string& what)
      : std::runtime_error("column " + std::to_string(column) + ": " + what), column(column) {}
  std::size_t column;
};

class Expression {
 public:
  // Throws ExpressionError. `dimension` limits the coordinates to x (1), x y (2) or x y z (3).
  Expression(const std::string& text, int dimension);
  ~Expression();
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;

  // The value at the point (coordinates past the dimension are ignored).
  double operator()(const std::array<double, 3>& x) const;
  const std::string& text() const { return text_; }
  // True if the value does not depend on the point.
  bool constant() const;

  struct Node;

 private:
  std::string text_;
  std::unique_ptr<Node> root_;
};

}  // namespace sphmol
