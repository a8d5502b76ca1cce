#include "tune_strategy.hpp"

#include <cmath>
#include <limits>
#include <map>

#include "parashade/errors.hpp"

namespace parashade::cli {

TuneStrategy parse_tune_strategy(const std::string& name) {
  for (TuneStrategy s : {TuneStrategy::brute, TuneStrategy::random, TuneStrategy::anneal})
    if (name == tune_strategy_name(s)) return s;
  throw UsageError("--strategy: unknown strategy '" + name + "' (valid: brute, random, anneal)");
}

const char* tune_strategy_name(TuneStrategy s) {
  switch (s) {
    case TuneStrategy::brute: return "brute";
    case TuneStrategy::random: return "random";
    case TuneStrategy::anneal: return "anneal";
  }
  return "?";
}

std::uint64_t TuneRandom::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::size_t TuneRandom::below(std::size_t n) { return std::size_t(next() % n); }

double TuneRandom::unit() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }

std::vector<std::size_t> visit_order(TuneStrategy s, std::size_t points, long first, const std::vector<bool>& planned,
                                     std::uint64_t seed) {
  TuneRandom rng(seed);
  std::vector<std::size_t> out;
  if (s == TuneStrategy::random) {
    for (std::size_t i = 0; i < points; ++i) out.push_back(i);
    rng.shuffle(out);
    return out;
  }
  std::vector<std::size_t> plain, plan;
  for (std::size_t i = 0; i < points; ++i)
    if (long(i) != first) (planned[i] ? plan : plain).push_back(i);
  rng.shuffle(plain);
  rng.shuffle(plan);
  if (first >= 0) out.push_back(std::size_t(first));
  out.insert(out.end(), plain.begin(), plain.end());
  out.insert(out.end(), plan.begin(), plan.end());
  return out;
}

std::vector<std::size_t> anneal(const std::vector<TunePoint>& points, const std::vector<int>& dims,
                                const std::function<double(std::size_t)>& cost, std::size_t max_evaluations, std::uint64_t seed, const std::function<bool()>& stop) {
  std::vector<std::size_t> order;
  if (points.empty() || max_evaluations == 0) return order;
  TuneRandom rng(seed);
  std::map<TunePoint, std::size_t> index;
  for (std::size_t i = 0; i < points.size(); ++i) index[points[i]] = i;
  std::map<std::size_t, double> seen;
  const auto evaluate = [&](std::size_t i) {
    const auto at = seen.find(i);
    if (at != seen.end()) return at->second;
    const double c = cost(i);
    seen[i] = c;
    order.push_back(i);
    return c;
  };
  // Kernel Tuner's neighbour: one parameter changed; mostly to an adjacent value, one time in five to any.
  const auto neighbour = [&](std::size_t at) {
    std::vector<std::size_t> any, adjacent;
    const TunePoint& p = points[at];
    for (std::size_t d = 0; d < p.size(); ++d) {
      TunePoint q = p;
      for (int v = 0; v < dims[d]; ++v) {
        if (v == p[d]) continue;
        q[d] = v;
        if (const auto f = index.find(q); f != index.end()) {
          any.push_back(f->second);
          if (std::abs(v - p[d]) == 1) adjacent.push_back(f->second);
        }
      }
    }
    const bool wide = rng.unit() < 0.2;
    const std::vector<std::size_t>& pick = wide || adjacent.empty() ? any : adjacent;
    if (pick.empty()) return rng.below(points.size());
    return pick[rng.below(pick.size())];
  };
  const double infeasible = std::numeric_limits<double>::infinity();
  const double t_start = 1.0, t_min = 0.001, alpha = 0.995;
  const double max_iter = std::ceil(std::log(t_min) / std::log(alpha));
  const double max_feval = double(max_evaluations);
  const auto done = [&] { return order.size() >= max_evaluations || order.size() >= points.size() || stop(); };

  std::size_t pos = rng.below(points.size());
  double old_cost = evaluate(pos);
  double t = t_start;
  std::size_t stuck = 0, seen_before = order.size();
  for (long iteration = 0; t > t_min && !done() && iteration <= 10 * long(max_iter); ++iteration) {
    const std::size_t next = neighbour(pos);
    const double new_cost = evaluate(next);
    double accept;
    if (old_cost == infeasible) accept = 1.0;
    else if (new_cost == infeasible) accept = 0.0;
    else if (new_cost < old_cost) accept = 1.0;
    else accept = std::exp(((old_cost - new_cost) / old_cost) / t);
    if (accept > rng.unit()) {
      pos = next;
      old_cost = new_cost;
    }
    t = t_start * std::pow(alpha, max_iter / max_feval * double(order.size()));
    stuck = order.size() == seen_before ? stuck + 1 : 0;
    seen_before = order.size();
    if (stuck > 100) {
      pos = rng.below(points.size());
      old_cost = evaluate(pos);
      stuck = 0;
    }
  }
  return order;
}

}  // namespace parashade::cli
