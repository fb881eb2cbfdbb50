// SPDX-License-Identifier: GPL-3.0-or-later
// LazyRadical: a double interval now, a Radical when a comparison needs it (see lazy_radical.h).
#include "exact/lazy_radical.h"

#include <CGAL/Interval_nt.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <utility>

#include "exact/interval_sign.h"

namespace roomcad::exact {
namespace {

/// Self-protecting intervals: each operation rounds outward whatever the caller's rounding.
using Interval = CGAL::Interval_nt<true>;

}  // namespace

struct LazyRadical::Node {
  enum class Op : std::uint8_t { constant, add, subtract, multiply, divide, negate, root };

  Node(Interval approx, Op op, double constant, const Node* a = nullptr, const Node* b = nullptr)
      : approx(approx), op(op), constant(constant), a(a), b(b) {}

  Interval approx;
  Op op;
  double constant;  ///< the value of a constant
  const Node* a;    ///< the operands (b: binary operations only)
  const Node* b;
  mutable std::optional<Radical> exact;

  /// @return the value in Radical, evaluating the operands first where they are not yet.
  const Radical& evaluate() const {
    if (exact) return *exact;
    switch (op) {
      case Op::constant: exact.emplace(constant); break;
      case Op::add: exact.emplace(a->evaluate() + b->evaluate()); break;
      case Op::subtract: exact.emplace(a->evaluate() - b->evaluate()); break;
      case Op::multiply: exact.emplace(a->evaluate() * b->evaluate()); break;
      case Op::divide: exact.emplace(a->evaluate() / b->evaluate()); break;
      case Op::negate: exact.emplace(-a->evaluate()); break;
      case Op::root: exact.emplace(sqrt(a->evaluate())); break;
    }
    return *exact;
  }
};

namespace {

/// The nodes of this thread's live values; a deque, so that a node never moves.
std::deque<LazyRadical::Node>& arena() {
  thread_local std::deque<LazyRadical::Node> nodes;
  return nodes;
}

using Op = LazyRadical::Node::Op;

/// @return a value whose node, made of `node_arguments`, lives in this thread's arena.
template <class... Args>
LazyRadical new_value(Args&&... node_arguments) {
  return {LazyRadical::FromNode{}, &arena().emplace_back(std::forward<Args>(node_arguments)...)};
}

}  // namespace

LazyRadical::Scope::Scope() : entry_size_(arena().size()) {}
LazyRadical::Scope::~Scope() {
  std::deque<Node>& nodes = arena();
  while (nodes.size() > entry_size_) nodes.pop_back();
}

LazyRadical::LazyRadical(double x) : LazyRadical(new_value(Interval(x), Op::constant, x)) {}

// An interval holding zero divides to the whole line: comparisons with the quotient evaluate.
LazyRadical operator+(const LazyRadical& a, const LazyRadical& b) {
  return new_value(a.node_->approx + b.node_->approx, Op::add, 0.0, a.node_, b.node_);
}
LazyRadical operator-(const LazyRadical& a, const LazyRadical& b) {
  return new_value(a.node_->approx - b.node_->approx, Op::subtract, 0.0, a.node_, b.node_);
}
LazyRadical operator*(const LazyRadical& a, const LazyRadical& b) {
  return new_value(a.node_->approx * b.node_->approx, Op::multiply, 0.0, a.node_, b.node_);
}
LazyRadical operator/(const LazyRadical& a, const LazyRadical& b) {
  return new_value(a.node_->approx / b.node_->approx, Op::divide, 0.0, a.node_, b.node_);
}
LazyRadical LazyRadical::operator-() const {
  return new_value(-node_->approx, Op::negate, 0.0, node_);
}
LazyRadical sqrt(const LazyRadical& x) {
  return new_value(CGAL::sqrt(x.node_->approx), Op::root, 0.0, x.node_);
}

int sign(const LazyRadical& x) {
  const int s = detail::interval_sign(x.node_->approx);
  return s != detail::kUnknownSign ? s : sign(x.exact());
}

int compare(const LazyRadical& a, const LazyRadical& b) {
  if (a.node_ == b.node_) return 0;
  const int s = detail::interval_sign(a.node_->approx - b.node_->approx);
  return s != detail::kUnknownSign ? s : sign(a.exact() - b.exact());
}

const Radical& LazyRadical::exact() const { return node_->evaluate(); }
bool LazyRadical::is_evaluated() const { return node_->exact.has_value(); }

}  // namespace roomcad::exact
