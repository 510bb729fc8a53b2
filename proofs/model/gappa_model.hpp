// A reader and double-precision evaluator for the subset of Gappa that the
// models in proofs/gappa/ are written in, so that a test can run a model's
// computed expression on the code's inputs and compare bits.
//
// Subset: `# ...` comments; `@name = float<53, ne>;` or `float<ieee_64, ne>;`
// (binary64, round to nearest even); `name = expression;` with + - * /, unary
// -, parentheses, numbers (`4`, `1b-3`), `fma(a, b, c)`, `sqrt(x)` and
// `name(x)` for a declared rounding; the proposition `{ ... }` and the hints
// after it are skipped. Anything else is an error, never silently ignored.
// A free variable whose name ends in `_underflow` evaluates to 0 (evaluator).
//
// Evaluation in double follows the model's roundings, not the code's: a node
// under a rounding operator is one IEEE operation on operands whose real value
// double holds exactly; a node outside one must itself be exact in double
// (checked with error-free transformations), else evaluation fails. So a model
// that rounds twice where the code rounds once, or once where the code rounds
// twice, gives other bits, and the comparison with the code catches it.
#pragma once

#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace contact::proofs {

struct node {
  enum class kind { number, variable, negate, add, subtract, multiply, divide, fma, sqrt, round };
  kind what = kind::number;
  double number = 0;      // kind::number
  std::string name;       // kind::variable; kind::round: the rounding operator's name
  std::vector<std::shared_ptr<node>> operands;
};
using node_ptr = std::shared_ptr<node>;

struct model_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct model {
  std::set<std::string> roundings;              // operators declared `@name = float<53, ne>`
  std::map<std::string, node_ptr> definitions;  // `name = expression;`
};

namespace model_detail {

class parser {
 public:
  explicit parser(std::string text) : text_(strip_comments(std::move(text))) {}

  model parse() {
    model m;
    for (;;) {
      skip_space();
      if (at_end()) break;
      if (peek() == '{') break;  // the proposition and the hints after it: not part of the model
      if (peek() == '@') {
        ++pos_;
        const std::string name = identifier();
        expect('=');
        parse_rounding();
        expect(';');
        m.roundings.insert(name);
        continue;
      }
      const std::string name = identifier();
      expect('=');
      roundings_ = &m.roundings;
      node_ptr value = expression();
      expect(';');
      if (!m.definitions.emplace(name, value).second) fail("`" + name + "` defined twice");
    }
    return m;
  }

 private:
  static std::string strip_comments(std::string text) {
    std::string out;
    bool comment = false;
    for (char c : text) {
      if (c == '#') comment = true;
      if (c == '\n') comment = false;
      if (!comment) out += c;
    }
    return out;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw model_error("gappa model, at offset " + std::to_string(pos_) + ": " + what);
  }
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  void skip_space() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skip_space();
    if (peek() != c) return false;
    ++pos_;
    return true;
  }
  void expect(char c) {
    if (!accept(c)) fail(std::string("expected '") + c + "'");
  }
  std::string identifier() {
    skip_space();
    const std::size_t start = pos_;
    while (!at_end() && (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_')) ++pos_;
    if (start == pos_ || std::isdigit(static_cast<unsigned char>(text_[start]))) fail("expected a name");
    return text_.substr(start, pos_ - start);
  }
  // float<53, ne> or float<ieee_64, ne>: the two spellings of binary64 to nearest even
  void parse_rounding() {
    if (identifier() != "float") fail("only float<...> roundings are supported");
    expect('<');
    skip_space();
    std::string format;
    while (!at_end() && peek() != ',') format += text_[pos_++];
    while (!format.empty() && std::isspace(static_cast<unsigned char>(format.back()))) format.pop_back();
    expect(',');
    const std::string mode = identifier();
    expect('>');
    if ((format != "53" && format != "ieee_64") || mode != "ne")
      fail("rounding float<" + format + ", " + mode + "> is not binary64 to nearest even");
  }

  node_ptr make(node::kind k, std::vector<node_ptr> operands) {
    auto n = std::make_shared<node>();
    n->what = k;
    n->operands = std::move(operands);
    return n;
  }

  node_ptr expression() {
    node_ptr left = term();
    for (;;) {
      if (accept('+')) left = make(node::kind::add, {left, term()});
      else if (accept('-')) left = make(node::kind::subtract, {left, term()});
      else return left;
    }
  }
  node_ptr term() {
    node_ptr left = unary();
    for (;;) {
      if (accept('*')) left = make(node::kind::multiply, {left, unary()});
      else if (accept('/')) left = make(node::kind::divide, {left, unary()});
      else return left;
    }
  }
  node_ptr unary() {
    if (accept('-')) return make(node::kind::negate, {unary()});
    return primary();
  }
  std::vector<node_ptr> arguments(std::size_t count) {
    expect('(');
    std::vector<node_ptr> args{expression()};
    while (accept(',')) args.push_back(expression());
    expect(')');
    if (args.size() != count) fail("wrong number of arguments");
    return args;
  }
  node_ptr primary() {
    skip_space();
    if (accept('(')) {
      node_ptr inner = expression();
      expect(')');
      return inner;
    }
    if (std::isdigit(static_cast<unsigned char>(peek()))) return number();
    const std::string name = identifier();
    skip_space();
    if (peek() != '(') {
      auto n = make(node::kind::variable, {});
      n->name = name;
      return n;
    }
    if (name == "fma") return make(node::kind::fma, arguments(3));
    if (name == "sqrt") return make(node::kind::sqrt, arguments(1));
    if (roundings_->count(name)) {
      auto n = make(node::kind::round, arguments(1));
      n->name = name;
      return n;
    }
    fail("unknown function `" + name + "`");
  }
  // 4, 1b-3 (m * 2^e): an integer times a power of two, which must be a normal double
  node_ptr number() {
    const std::size_t start = pos_;
    while (!at_end() && std::isdigit(static_cast<unsigned char>(peek()))) ++pos_;
    const std::string mantissa = text_.substr(start, pos_ - start);
    if (peek() == '.') fail("decimal numbers are not supported; write m b e");
    long exponent = 0;
    if (peek() == 'b') {
      ++pos_;
      const std::size_t e_start = pos_;
      if (peek() == '-') ++pos_;
      while (!at_end() && std::isdigit(static_cast<unsigned char>(peek()))) ++pos_;
      exponent = std::stol(text_.substr(e_start, pos_ - e_start));
    }
    if (mantissa.size() > 15) fail("number " + mantissa + " has more digits than a double holds exactly here");
    const double value = std::ldexp(double(std::stoll(mantissa)), static_cast<int>(exponent));
    if (!std::isfinite(value) || (value != 0 && std::fabs(value) < 0x1p-1022))
      fail("number " + mantissa + "b" + std::to_string(exponent) + " is not a normal double");
    auto n = make(node::kind::number, {});
    n->number = value;
    return n;
  }

  std::string text_;
  std::size_t pos_ = 0;
  const std::set<std::string>* roundings_ = nullptr;
};

}  // namespace model_detail

inline model parse_model(const std::string& text) { return model_detail::parser(text).parse(); }

// Evaluates a model's names on given inputs (the model's free variables).
class evaluator {
 public:
  evaluator(const model& m, std::map<std::string, double> inputs) : model_(m), inputs_(std::move(inputs)) {}

  // The double that the named expression's real value is, following the model's roundings.
  double value_of(const std::string& name) { return exact(variable_node(name)); }

 private:
  node_ptr variable_node(const std::string& name) {
    auto n = std::make_shared<node>();
    n->what = node::kind::variable;
    n->name = name;
    return n;
  }

  static bool is_underflow_term(const std::string& name) {
    const std::string suffix = "_underflow";
    return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  }

  [[noreturn]] static void not_exact(const char* what) {
    throw model_error(std::string("an unrounded ") + what + " of the model is not exact in double");
  }

  // A rounded result: binary64 with the model's unbounded exponent only agrees with
  // double while nothing over- or underflows, so a result outside the normal range fails.
  static double checked(double x) {
    if (!std::isfinite(x) || (x != 0 && std::fabs(x) < 0x1p-1022))
      throw model_error("a rounded value leaves binary64's normal range: the model's unbounded exponent does not apply");
    return x;
  }

  // The real value of n, which must be a double.
  double exact(const node_ptr& n) {
    using k = node::kind;
    switch (n->what) {
      case k::number: return n->number;
      case k::variable: {
        if (auto in = inputs_.find(n->name); in != inputs_.end()) return in->second;
        auto def = model_.definitions.find(n->name);
        // A model writes a rounding that may land on double's subnormal grid as
        // rnd(x) + NAME_underflow: the underflow term, bounded by a hypothesis, is how
        // far that grid's rounding lies from the unbounded exponent's, and it is 0
        // wherever the rounded value is normal (or exact). Here every rounded value
        // is normal, or evaluation fails (checked), so the term is 0.
        if (def == model_.definitions.end() && is_underflow_term(n->name)) return 0;
        if (def == model_.definitions.end()) throw model_error("`" + n->name + "` is neither an input nor defined");
        if (!visiting_.insert(n->name).second) throw model_error("`" + n->name + "` is defined in terms of itself");
        const double v = exact(def->second);
        visiting_.erase(n->name);
        return v;
      }
      case k::negate: return -exact(n->operands[0]);
      case k::round: return checked(rounded(n->operands[0]));
      case k::add: case k::subtract: {
        const double a = exact(n->operands[0]), b = n->what == k::add ? exact(n->operands[1]) : -exact(n->operands[1]);
        const double sum = a + b;  // exact iff the TwoSum error is zero
        const double b_virtual = sum - a, a_virtual = sum - b_virtual;
        if ((a - a_virtual) + (b - b_virtual) != 0 || !std::isfinite(sum)) not_exact("sum");
        return sum;
      }
      case k::multiply: {
        const double a = exact(n->operands[0]), b = exact(n->operands[1]);
        const double p = a * b;
        if (std::fma(a, b, -p) != 0 || !std::isfinite(p) || (p != 0 && std::fabs(p) < 0x1p-1022)) not_exact("product");
        return p;
      }
      case k::divide: {
        const double a = exact(n->operands[0]), b = exact(n->operands[1]);
        const double q = a / b;
        if (std::fma(q, b, -a) != 0 || !std::isfinite(q) || (q != 0 && std::fabs(q) < 0x1p-1022)) not_exact("quotient");
        return q;
      }
      case k::sqrt: {
        const double a = exact(n->operands[0]);
        const double r = std::sqrt(a);
        if (std::fma(r, r, -a) != 0) not_exact("square root");
        return r;
      }
      case k::fma: not_exact("fma");  // a * b + c unrounded: not a double in general, and never written so
    }
    throw model_error("unreachable");
  }

  // The value of round(n): one IEEE operation on exact operands.
  double rounded(const node_ptr& n) {
    using k = node::kind;
    const auto& x = n->operands;
    switch (n->what) {
      case k::number: case k::variable: case k::negate: case k::round: return exact(n);
      case k::add: return exact(x[0]) + exact(x[1]);
      case k::subtract: return exact(x[0]) - exact(x[1]);
      case k::multiply: return exact(x[0]) * exact(x[1]);
      case k::divide: return exact(x[0]) / exact(x[1]);
      case k::sqrt: return std::sqrt(exact(x[0]));
      case k::fma: return std::fma(exact(x[0]), exact(x[1]), exact(x[2]));
    }
    throw model_error("unreachable");
  }

  const model& model_;
  std::map<std::string, double> inputs_;
  std::set<std::string> visiting_;
};

}  // namespace contact::proofs
