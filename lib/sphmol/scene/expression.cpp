#include "sphmol/scene/expression.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

namespace sphmol {

struct Expression::Node {
  enum class Op { number, coordinate, add, sub, mul, div, pow, neg, func } op = Op::number;
  double value = 0.0;                 // number
  int axis = 0;                       // coordinate
  double (*f)(double) = nullptr;      // func
  std::unique_ptr<Node> a, b;

  double eval(const std::array<double, 3>& x) const {
    switch (op) {
      case Op::number: return value;
      case Op::coordinate: return x[static_cast<std::size_t>(axis)];
      case Op::add: return a->eval(x) + b->eval(x);
      case Op::sub: return a->eval(x) - b->eval(x);
      case Op::mul: return a->eval(x) * b->eval(x);
      case Op::div: return a->eval(x) / b->eval(x);
      case Op::pow: return std::pow(a->eval(x), b->eval(x));
      case Op::neg: return -a->eval(x);
      case Op::func: return f(a->eval(x));
    }
    return 0.0;
  }
  bool constant() const {
    if (op == Op::coordinate) return false;
    return (!a || a->constant()) && (!b || b->constant());
  }
};

namespace {

using Node = Expression::Node;
using Ptr = std::unique_ptr<Node>;

double f_sin(double v) { return std::sin(v); }
double f_cos(double v) { return std::cos(v); }
double f_tan(double v) { return std::tan(v); }
double f_exp(double v) { return std::exp(v); }
double f_sqrt(double v) { return std::sqrt(v); }
double f_abs(double v) { return std::abs(v); }

// Recursive descent over the grammar
//   sum     = product { ("+" | "-") product }
//   product = unary { ("*" | "/") unary }
//   unary   = "-" unary | "+" unary | power
//   power   = atom [ "^" unary ]
//   atom    = number | name | name "(" sum ")" | "(" sum ")"
class Parser {
 public:
  Parser(const std::string& s, int dimension) : s_(s), dim_(dimension) {}

  Ptr parse() {
    skip();
    if (pos_ == s_.size()) throw ExpressionError(1, "empty expression");
    Ptr e = sum();
    skip();
    if (pos_ != s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
    return e;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw ExpressionError(pos_ + 1, what); }
  void skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool take(char c) {
    skip();
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  static Ptr binary(Node::Op op, Ptr a, Ptr b) {
    auto n = std::make_unique<Node>();
    n->op = op;
    n->a = std::move(a);
    n->b = std::move(b);
    return n;
  }
  Ptr sum() {
    Ptr e = product();
    while (true) {
      if (take('+')) e = binary(Node::Op::add, std::move(e), product());
      else if (take('-')) e = binary(Node::Op::sub, std::move(e), product());
      else return e;
    }
  }
  Ptr product() {
    Ptr e = unary();
    while (true) {
      if (take('*')) e = binary(Node::Op::mul, std::move(e), unary());
      else if (take('/')) e = binary(Node::Op::div, std::move(e), unary());
      else return e;
    }
  }
  Ptr unary() {
    if (take('-')) {
      auto n = std::make_unique<Node>();
      n->op = Node::Op::neg;
      n->a = unary();
      return n;
    }
    if (take('+')) return unary();
    return power();
  }
  Ptr power() {
    Ptr e = atom();
    if (take('^')) return binary(Node::Op::pow, std::move(e), unary());
    return e;
  }
  Ptr atom() {
    skip();
    if (pos_ == s_.size()) fail("expected a number, a name or '(' at the end of the expression");
    const char c = s_[pos_];
    if (take('(')) {
      Ptr e = sum();
      if (!take(')')) fail("expected ')'");
      return e;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    fail("unexpected '" + std::string(1, c) + "'");
  }
  Ptr number() {
    const std::size_t start = pos_;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(s_.data() + pos_, s_.data() + s_.size(), v);
    if (ec != std::errc{}) fail("malformed number");
    pos_ = static_cast<std::size_t>(end - s_.data());
    if (pos_ < s_.size() && (std::isalpha(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) {
      pos_ = start;
      fail("malformed number (write a product as 2*x)");
    }
    auto n = std::make_unique<Node>();
    n->value = v;
    return n;
  }
  Ptr name() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
    const std::string w = s_.substr(start, pos_ - start);
    static const char* const axes[] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d)
      if (w == axes[d]) {
        if (d >= dim_) {
          pos_ = start;
          fail("'" + w + "' is not a coordinate in " + std::to_string(dim_) + "D");
        }
        auto n = std::make_unique<Node>();
        n->op = Node::Op::coordinate;
        n->axis = d;
        return n;
      }
    if (w == "pi") {
      auto n = std::make_unique<Node>();
      n->value = std::numbers::pi;
      return n;
    }
    static const std::vector<std::pair<std::string, double (*)(double)>> funcs = {
        {"sin", f_sin}, {"cos", f_cos}, {"tan", f_tan}, {"exp", f_exp}, {"sqrt", f_sqrt}, {"abs", f_abs}};
    for (const auto& [fname, fn] : funcs)
      if (w == fname) {
        if (!take('(')) fail("expected '(' after the function " + w);
        auto n = std::make_unique<Node>();
        n->op = Node::Op::func;
        n->f = fn;
        n->a = sum();
        if (!take(')')) fail("expected ')' closing " + w + "(");
        return n;
      }
    pos_ = start;
    fail("unknown name '" + w + "' (known: x" + std::string(dim_ > 1 ? " y" : "") + std::string(dim_ > 2 ? " z" : "") +
         " pi sin cos tan exp sqrt abs)");
  }

  const std::string& s_;
  int dim_;
  std::size_t pos_ = 0;
};

}  // namespace

Expression::Expression(const std::string& text, int dimension) : text_(text) {
  root_ = Parser(text_, dimension).parse();
}
Expression::~Expression() = default;
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;

double Expression::operator()(const std::array<double, 3>& x) const { return root_->eval(x); }
bool Expression::constant() const { return root_->constant(); }

}  // namespace sphmol
