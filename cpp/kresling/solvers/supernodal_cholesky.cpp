#include "kresling/solvers/supernodal_cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>
#include <thread>

#include <Eigen/CholmodSupport>

#include "kresling/solvers/supernodal_kernels.hpp"

namespace kresling::solvers {

namespace {

// A supernode above the threads' subtrees shares its work among the threads (it waits for
// them anyway) from this many flops up (its own, as weigh() counts them): below, starting
// the threads costs more than it saves.
constexpr double kSharedSupernodeFlops = 1e7;
// Columns of the panels in which a shared supernode factorises its own columns.
constexpr int kSharedPanel = 96;

// Runs work(0) here and work(1) ... work(threads - 1) on threads of their own, concurrently.
template <class Work>
void on_threads(int threads, const Work& work) {
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& thread : pool) thread.join();
}

// Bounds splitting the columns [0, ncol) of a lower trapezoid of nrow rows into `parts`
// ranges of about equal work (column j, nrow - j entries): parts + 1 ascending offsets.
std::vector<int> balanced_columns(int nrow, int ncol, int parts) {
  std::vector<int> bounds(parts + 1, ncol);
  bounds[0] = 0;
  const double m = nrow, total = ncol * (m - 0.5 * ncol);
  for (int t = 1; t < parts; ++t) {
    // c (m - c / 2) = total t / parts, the smaller root.
    const double share = total * t / parts;
    const double c = m - std::sqrt(std::max(m * m - 2.0 * share, 0.0));
    bounds[t] = std::clamp(static_cast<int>(std::lround(c)), bounds[t - 1], ncol);
  }
  return bounds;
}

}  // namespace

struct SupernodalCholesky::Impl {
  // The symbolic factor (CHOLMOD's layout): supernode s holds the columns
  // [super[s], super[s+1]) of the permuted matrix; its rows are rows[pi[s] .. pi[s+1]) (its
  // own columns first, then the rows below, ascending) and its values the column-major
  // block of those rows by its columns at values[px[s]].
  Index n = 0;
  int nsuper = 0;
  std::vector<int> perm;            // permuted index k -> original index
  std::vector<int> super, pi, px, rows;
  std::vector<int> column_super;    // permuted column -> its supernode
  std::vector<int> parent;          // supernodal elimination tree (-1: a root)
  std::vector<Index> destination;   // K's stored entry -> its slot in values (-1: upper)
  Index stored_entries = 0;
  std::vector<double> values;
  bool ldlt = false;                // the values hold L D L^T (unit L, D on its diagonal)
  std::size_t largest_update = 0;   // entries of the largest update block
  Index widest_below = 0;           // rows below a supernode's own columns, at most
  // Parallel schedule: the supernodes each thread factorises (whole subtrees, ascending),
  // then the rest ("top", ascending) on the calling thread.
  std::vector<std::vector<int>> subtrees;
  std::vector<int> top;
  std::vector<char> shared;         // per supernode of top: its work shared by the threads
  bool ok = false;
  const SupernodalKernels* kernels = &supernodal_kernels();

  // Per-thread scratch: the descendants waiting to update each supernode (a list through
  // `next`, heads per supernode), the relative row map and the update block.
  struct Scratch {
    std::vector<int> head;
    std::vector<int> map;
    std::vector<int> relative;
    std::vector<double> update;
    std::vector<double> scaled;  // LDL^T: a descendant's rows times its D
  };
  std::vector<int> next, position;  // per supernode: next in its list; its next row to use
  std::vector<Scratch> per_thread;  // scratch of each thread, sized by analyze

  SupernodalCholesky::Analysis symbolic(const SparseMatrix& K,
                                        const std::vector<int>& orderings);
  void build_tree();
  void map_entries(const SparseMatrix& K);
  void schedule(int threads);
  // The tree's supernodes weighed for the schedule (their own and their subtree's flops).
  struct Weights {
    std::vector<double> work, own;
    std::vector<std::vector<int>> children;
    std::vector<int> roots;
  };
  Weights weigh() const;
  std::vector<int> split_tree(const Weights& w, int threads) const;
  void assign_subtrees(const Weights& w, const std::vector<int>& pieces, int threads);
  bool factor_supernode(int s, Scratch& scratch);
  bool factor_supernode_shared(int s);
  bool factor_top();
  void subtract_update(const double* L, int ld, int drow, int dcol, int p1, int p2,
                       const int* target_rows, double* S, int nrow, int k1, Scratch& scratch);
  bool factorize(const SparseMatrix& K, bool with_d);
  void link(int d, int p_next, std::vector<int>& head);
};

SupernodalCholesky::SupernodalCholesky() : impl_(std::make_unique<Impl>()) {}
SupernodalCholesky::~SupernodalCholesky() = default;

double SupernodalCholesky::factor_nonzeros() const {
  return static_cast<double>(impl_->values.size());
}
int SupernodalCholesky::supernodes() const { return impl_->nsuper; }
int SupernodalCholesky::shared_supernodes() const {
  return static_cast<int>(std::count(impl_->shared.begin(), impl_->shared.end(), 1));
}
int SupernodalCholesky::working_threads() const {
  int working = 0;
  for (const auto& share : impl_->subtrees) working += share.empty() ? 0 : 1;
  return working;
}

SupernodalCholesky::Analysis SupernodalCholesky::analyze(const SparseMatrix& K,
                                                         const std::vector<int>& orderings,
                                                         int threads) {
  Impl& m = *impl_;
  const SupernodalKernels* kernels = m.kernels;
  m = Impl();
  m.kernels = kernels;
  m.n = K.rows();
  Analysis analysis;
  if (m.n == 0) return analysis;
  if (orderings.empty() || orderings.size() > CHOLMOD_MAXMETHODS) {
    throw std::invalid_argument("SupernodalCholesky::analyze: orderings must name 1 to " +
                                std::to_string(CHOLMOD_MAXMETHODS) + " orderings");
  }
  analysis = m.symbolic(K, orderings);
  m.build_tree();
  m.map_entries(K);
  m.next.assign(m.nsuper, -1);
  m.position.assign(m.nsuper, 0);
  use_threads(threads);
  return analysis;
}

// CHOLMOD's supernodal symbolic analysis of K with the best of `orderings`: the
// permutation and the supernodes' columns, rows and value offsets; the values zeroed.
SupernodalCholesky::Analysis SupernodalCholesky::Impl::symbolic(
    const SparseMatrix& K, const std::vector<int>& orderings) {
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SUPERNODAL;
  common.nmethods = static_cast<int>(orderings.size());
  for (std::size_t k = 0; k < orderings.size(); ++k) common.method[k].ordering = orderings[k];
  common.postorder = 1;
  SparseMatrix lower = K.triangularView<Eigen::Lower>();
  lower.makeCompressed();
  cholmod_sparse A = Eigen::viewAsCholmod(lower);
  A.stype = -1;
  cholmod_factor* L = cholmod_analyze(&A, &common);
  if (!L || !L->is_super) {
    if (L) cholmod_free_factor(&L, &common);
    cholmod_finish(&common);
    throw std::runtime_error("SupernodalCholesky: CHOLMOD's symbolic analysis failed");
  }
  nsuper = static_cast<int>(L->nsuper);
  auto copy = [](const void* p, std::size_t count) {
    const int* x = static_cast<const int*>(p);
    return std::vector<int>(x, x + count);
  };
  perm = copy(L->Perm, static_cast<std::size_t>(n));
  super = copy(L->super, nsuper + 1);
  pi = copy(L->pi, nsuper + 1);
  px = copy(L->px, nsuper + 1);
  rows = copy(L->s, static_cast<std::size_t>(pi[nsuper]));
  values.assign(static_cast<std::size_t>(px[nsuper]), 0.0);
  const auto& kept = common.method[common.selected];
  const SupernodalCholesky::Analysis analysis{kept.ordering, kept.lnz, kept.fl};
  cholmod_free_factor(&L, &common);
  cholmod_finish(&common);
  return analysis;
}

// Each column's supernode, the supernodal elimination tree and the sizes of the largest
// update block and of the widest part below a supernode's own columns.
void SupernodalCholesky::Impl::build_tree() {
  column_super.resize(static_cast<std::size_t>(n));
  parent.assign(nsuper, -1);
  for (int s = 0; s < nsuper; ++s) {
    for (int k = super[s]; k < super[s + 1]; ++k) column_super[k] = s;
  }
  for (int s = 0; s < nsuper; ++s) {
    const int ncol = super[s + 1] - super[s], nrow = pi[s + 1] - pi[s];
    if (nrow > ncol) parent[s] = column_super[rows[pi[s] + ncol]];
    largest_update = std::max(largest_update,
                              static_cast<std::size_t>(nrow) * static_cast<std::size_t>(nrow));
    widest_below = std::max<Index>(widest_below, nrow - ncol);
  }
}

// Where each stored entry of K goes in the factor's values (its lower triangle, permuted).
void SupernodalCholesky::Impl::map_entries(const SparseMatrix& K) {
  std::vector<int> inverse(static_cast<std::size_t>(n));
  for (Index k = 0; k < n; ++k) inverse[perm[k]] = static_cast<int>(k);
  destination.clear();
  destination.reserve(static_cast<std::size_t>(K.nonZeros()));
  for (Index j = 0; j < K.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
      if (it.row() < it.col()) {
        destination.push_back(-1);
        continue;
      }
      const int a = inverse[it.row()], b = inverse[it.col()];
      const int row = std::max(a, b), col = std::min(a, b);
      const int s = column_super[col];
      const int* first = rows.data() + pi[s];
      const int* last = rows.data() + pi[s + 1];
      // The supernode's own columns come first (ascending), then the rows below (ascending).
      const int ncol = super[s + 1] - super[s];
      const int* found = row < super[s + 1] ? first + (row - super[s])
                                            : std::lower_bound(first + ncol, last, row);
      const Index nrow = pi[s + 1] - pi[s];
      destination.push_back(px[s] + (col - super[s]) * nrow + (found - first));
    }
  }
  stored_entries = K.nonZeros();
}

void SupernodalCholesky::use_instruction_set(InstructionSet set) {
  impl_->kernels = &supernodal_kernels(set);
}

InstructionSet SupernodalCholesky::instruction_set() const {
  return impl_->kernels->instruction_set;
}

void SupernodalCholesky::use_threads(int threads) {
  Impl& m = *impl_;
  if (m.n == 0) return;
  m.schedule(std::max(threads, 1));
  m.per_thread.resize(m.subtrees.size());
  for (auto& sc : m.per_thread) {
    sc.head.assign(m.nsuper, -1);
    sc.map.assign(static_cast<std::size_t>(m.n), 0);
    sc.relative.assign(static_cast<std::size_t>(m.n), 0);
    sc.update.resize(m.largest_update);
    sc.scaled.clear();  // sized by the first LDL^T
  }
}

// Splits the elimination tree into subtrees for the threads: starting from the roots, the
// heaviest subtree (by its dense kernels' flops) is replaced by its children, its root going
// to the top part (factorised after the threads: its large supernodes shared by them, the
// rest by one), for as long as that shortens the estimated time: the top part's work (as if
// on one thread) plus the larger of the heaviest subtree's and an even share of the rest.
// The subtrees go to the least loaded thread, heaviest first; then the top part's large
// supernodes are marked to be shared.
void SupernodalCholesky::Impl::schedule(int threads) {
  subtrees.assign(1, {});
  top.clear();
  shared.clear();
  const Weights w = weigh();
  if (threads <= 1 || nsuper < 2) {
    subtrees[0].resize(nsuper);
    for (int s = 0; s < nsuper; ++s) subtrees[0][s] = s;
    return;
  }
  assign_subtrees(w, split_tree(w, threads), threads);
  shared.assign(top.size(), 0);
  for (std::size_t k = 0; k < top.size(); ++k) {
    shared[k] = w.own[top[k]] >= kSharedSupernodeFlops;
  }
}

SupernodalCholesky::Impl::Weights SupernodalCholesky::Impl::weigh() const {
  Weights w;
  w.work.assign(nsuper, 0.0);
  w.own.assign(nsuper, 0.0);
  w.children.resize(nsuper);
  for (int s = 0; s < nsuper; ++s) {  // postordered: children come before parents
    // Its diagonal block, the rows below it, and the updates it sends up.
    const double c = super[s + 1] - super[s], b = pi[s + 1] - pi[s] - c;
    w.own[s] = c * c * c / 3.0 + c * c * b + c * b * b;
    w.work[s] += w.own[s];
    if (parent[s] >= 0) {
      w.work[parent[s]] += w.work[s];
      w.children[parent[s]].push_back(s);
    } else {
      w.roots.push_back(s);
    }
  }
  return w;
}

// The roots of the subtrees the threads share, heaviest first (the supernodes above them
// go to the top part).
std::vector<int> SupernodalCholesky::Impl::split_tree(const Weights& w, int threads) const {
  const std::vector<double>& work = w.work;
  double total = 0.0;
  for (int r : w.roots) total += work[r];
  auto lighter = [&](int a, int b) { return work[a] < work[b]; };
  std::priority_queue<int, std::vector<int>, decltype(lighter)> open(lighter);
  for (int r : w.roots) open.push(r);
  double top_work = 0.0;
  auto makespan = [&](double top_part, double heaviest) {
    return top_part + std::max(heaviest, (total - top_part) / threads);
  };
  while (!open.empty() && !w.children[open.top()].empty()) {
    const int s = open.top();
    double next_heaviest = 0.0;
    for (int child : w.children[s]) next_heaviest = std::max(next_heaviest, work[child]);
    open.pop();
    if (!open.empty()) next_heaviest = std::max(next_heaviest, work[open.top()]);
    if (makespan(top_work + w.own[s], next_heaviest) >= makespan(top_work, work[s])) {
      open.push(s);
      break;
    }
    top_work += w.own[s];
    for (int child : w.children[s]) open.push(child);
  }
  std::vector<int> pieces;
  while (!open.empty()) {
    pieces.push_back(open.top());
    open.pop();
  }
  return pieces;
}

// Heaviest first to the least loaded thread; what no thread takes is the top part.
void SupernodalCholesky::Impl::assign_subtrees(const Weights& w, const std::vector<int>& pieces,
                                               int threads) {
  std::vector<double> load(threads, 0.0);
  std::vector<std::vector<int>> owned(threads);
  for (int piece : pieces) {
    const int t = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[t] += w.work[piece];
    owned[t].push_back(piece);
  }
  // A subtree of a postordered tree is a contiguous range ending at its root.
  std::vector<int> first(nsuper);
  for (int s = 0; s < nsuper; ++s) first[s] = s;
  for (int s = 0; s < nsuper; ++s) {
    if (parent[s] >= 0) first[parent[s]] = std::min(first[parent[s]], first[s]);
  }
  subtrees.assign(threads, {});
  std::vector<char> taken(nsuper, 0);
  for (int t = 0; t < threads; ++t) {
    for (int root : owned[t]) {
      for (int s = first[root]; s <= root; ++s) {
        subtrees[t].push_back(s);
        taken[s] = 1;
      }
    }
    std::sort(subtrees[t].begin(), subtrees[t].end());
  }
  for (int s = 0; s < nsuper; ++s) {
    if (!taken[s]) top.push_back(s);
  }
}

// Puts supernode d, whose next row to use is at offset p_next of its rows, on the list of
// the supernode that row belongs to (if any).
void SupernodalCholesky::Impl::link(int d, int p_next, std::vector<int>& head) {
  const int nrow = pi[d + 1] - pi[d];
  position[d] = p_next;
  if (p_next < nrow) {
    const int target = column_super[rows[pi[d] + p_next]];
    next[d] = head[target];
    head[target] = d;
  }
}

// S -= the update of a block L (rows [p1, drow) by rows [p1, p2), see SupernodalKernels),
// whose rows are target_rows, into the supernode S (nrow rows, first column k1) whose rows
// scratch.map locates.
void SupernodalCholesky::Impl::subtract_update(const double* L, int ld, int drow, int dcol,
                                                int p1, int p2, const int* target_rows,
                                                double* S, int nrow, int k1, Scratch& scratch) {
  const int n1 = p2 - p1, n2 = drow - p1;
  kernels->update(L, ld, drow, dcol, p1, p2, ldlt, scratch.update.data(), scratch.scaled.data());
  for (int i = 0; i < n2; ++i) scratch.relative[i] = scratch.map[target_rows[p1 + i]];
  for (int j = 0; j < n1; ++j) {
    double* column = S + static_cast<Index>(target_rows[p1 + j] - k1) * nrow;
    const double* c = scratch.update.data() + static_cast<Index>(j) * n2;
    for (int i = j; i < n2; ++i) column[scratch.relative[i]] -= c[i];
  }
}

// A large supernode of the top part, its work shared by the threads: each thread takes a
// range of its columns (of about equal work) and subtracts from them the updates of every
// waiting supernode, then its own columns factorise in panels, each panel's update of the
// columns after it shared alike. The threads write disjoint columns; the result differs from
// factor_supernode's only in rounding (the panels' updates are summed in another order).
bool SupernodalCholesky::Impl::factor_supernode_shared(int s) {
  const int k1 = super[s], ncol = super[s + 1] - k1, nrow = pi[s + 1] - pi[s];
  const int* srows = rows.data() + pi[s];
  const int threads = static_cast<int>(per_thread.size());
  for (auto& sc : per_thread) {
    for (int i = 0; i < nrow; ++i) sc.map[srows[i]] = i;
  }
  double* S = values.data() + px[s];
  // The waiting supernodes and the range of their rows in s's columns.
  struct Waiting { int d, p1, p2; };
  std::vector<Waiting> waiting;
  Scratch& main = per_thread[0];
  for (int d = main.head[s]; d >= 0; d = next[d]) {
    const int drow = pi[d + 1] - pi[d];
    const int* drows = rows.data() + pi[d];
    int p2 = position[d];
    while (p2 < drow && drows[p2] < k1 + ncol) ++p2;
    waiting.push_back({d, position[d], p2});
  }
  main.head[s] = -1;
  const std::vector<int> columns = balanced_columns(nrow, ncol, threads);
  on_threads(threads, [&](int t) {
    for (const Waiting& w : waiting) {
      const int* drows = rows.data() + pi[w.d];
      const int q1 = static_cast<int>(
          std::lower_bound(drows + w.p1, drows + w.p2, k1 + columns[t]) - drows);
      const int q2 = static_cast<int>(
          std::lower_bound(drows + q1, drows + w.p2, k1 + columns[t + 1]) - drows);
      if (q1 == q2) continue;
      const int drow = pi[w.d + 1] - pi[w.d], dcol = super[w.d + 1] - super[w.d];
      subtract_update(values.data() + px[w.d], drow, drow, dcol, q1, q2, drows, S, nrow, k1,
                      per_thread[t]);
    }
  });
  for (const Waiting& w : waiting) link(w.d, w.p2, main.head);
  for (int k = 0; k < ncol; k += kSharedPanel) {
    const int width = std::min(kSharedPanel, ncol - k);
    double* panel = S + static_cast<Index>(k) * nrow + k;
    if (!kernels->factor(panel, nrow, nrow - k, width, ldlt)) return false;
    const int after = ncol - k - width;
    if (after == 0) continue;
    const std::vector<int> split = balanced_columns(nrow - k - width, after, threads);
    on_threads(threads, [&](int t) {
      if (split[t] == split[t + 1]) return;
      // The panel is a supernode of its own whose rows are s's from k on.
      subtract_update(panel, nrow, nrow - k, width, width + split[t], width + split[t + 1],
                      srows + k, S, nrow, k1, per_thread[t]);
    });
  }
  link(s, ncol, main.head);
  return true;
}

// Left-looking: the updates of every supernode waiting on s, then s's diagonal block and
// the rows below it.
bool SupernodalCholesky::Impl::factor_supernode(int s, Scratch& scratch) {
  const int k1 = super[s], k2 = super[s + 1], ncol = k2 - k1;
  const int nrow = pi[s + 1] - pi[s];
  const int* srows = rows.data() + pi[s];
  for (int i = 0; i < nrow; ++i) scratch.map[srows[i]] = i;
  double* S = values.data() + px[s];
  int d = scratch.head[s];
  scratch.head[s] = -1;
  while (d >= 0) {
    const int d_next = next[d];
    const int dcol = super[d + 1] - super[d], drow = pi[d + 1] - pi[d];
    const int* drows = rows.data() + pi[d];
    const int p1 = position[d];
    int p2 = p1;
    while (p2 < drow && drows[p2] < k2) ++p2;
    subtract_update(values.data() + px[d], drow, drow, dcol, p1, p2, drows, S, nrow, k1, scratch);
    link(d, p2, scratch.head);
    d = d_next;
  }
  if (!kernels->factor(S, nrow, nrow, ncol, ldlt)) return false;
  link(s, ncol, scratch.head);
  return true;
}

bool SupernodalCholesky::factorize(const SparseMatrix& K) { return impl_->factorize(K, false); }

bool SupernodalCholesky::factorize_ldlt(const SparseMatrix& K) {
  return impl_->factorize(K, true);
}

VectorX SupernodalCholesky::ldlt_diagonal() const {
  const Impl& m = *impl_;
  VectorX d(m.n);
  for (int s = 0; s < m.nsuper; ++s) {
    const int nrow = m.pi[s + 1] - m.pi[s];
    for (int k = m.super[s]; k < m.super[s + 1]; ++k) {
      d[k] = m.values[m.px[s] + static_cast<std::size_t>(k - m.super[s]) * (nrow + 1)];
    }
  }
  return d;
}

bool SupernodalCholesky::Impl::factorize(const SparseMatrix& K, bool with_d) {
  Impl& m = *this;
  m.ok = false;
  m.ldlt = with_d;
  if (K.rows() != m.n || K.nonZeros() != m.stored_entries) {
    throw std::invalid_argument("SupernodalCholesky::factorize: the matrix's pattern is not "
                                "the analysed one");
  }
  if (m.n == 0) return m.ok = true;
  std::fill(m.values.begin(), m.values.end(), 0.0);
  const double* x = K.valuePtr();
  for (std::size_t k = 0; k < m.destination.size(); ++k) {
    if (m.destination[k] >= 0) m.values[m.destination[k]] += x[k];
  }
  const int threads = static_cast<int>(m.subtrees.size());
  std::vector<Impl::Scratch>& scratch = m.per_thread;
  for (auto& sc : scratch) {
    std::fill(sc.head.begin(), sc.head.end(), -1);
    if (with_d && sc.scaled.size() < m.largest_update) sc.scaled.resize(m.largest_update);
  }
  std::vector<char> good(threads, 1);
  auto run = [&](int t) {
    for (int s : m.subtrees[t]) {
      if (!m.factor_supernode(s, scratch[t])) {
        good[t] = 0;
        return;
      }
    }
  };
  on_threads(threads, run);
  if (std::find(good.begin(), good.end(), 0) != good.end()) return false;
  if (!m.factor_top()) return false;
  m.ok = true;
  return true;
}

// The supernodes above the threads' subtrees, after them: the large ones shared by the
// threads, the rest on the calling thread.
bool SupernodalCholesky::Impl::factor_top() {
  if (top.empty()) return true;
  // The subtrees' supernodes wait in each thread's lists: merge them into the first's.
  Scratch& main = per_thread[0];
  for (std::size_t t = 1; t < per_thread.size(); ++t) {
    for (int s : top) {
      int d = per_thread[t].head[s];
      while (d >= 0) {
        const int d_next = next[d];
        next[d] = main.head[s];
        main.head[s] = d;
        d = d_next;
      }
    }
  }
  for (std::size_t k = 0; k < top.size(); ++k) {
    if (!(shared[k] ? factor_supernode_shared(top[k]) : factor_supernode(top[k], main))) {
      return false;
    }
  }
  return true;
}

// Forward and back substitution, supernode by supernode, column by column: the supernodes
// of small models are a few columns wide, where plain loops over a column (contiguous in the
// factor) beat the dense triangular solver's per-call overhead. The rows below a supernode's
// own columns are gathered into (or scattered from) a contiguous buffer once per supernode,
// so that the work on them is a contiguous, vectorised product per column instead of an
// indexed access per entry.
VectorX SupernodalCholesky::solve(const VectorX& b) const {
  const Impl& m = *impl_;
  if (!m.ok) throw std::logic_error("SupernodalCholesky::solve called without a factorisation");
  using Column = Eigen::Map<const VectorX>;
  VectorX y(m.n);
  for (Index k = 0; k < m.n; ++k) y[k] = b[m.perm[k]];
  double* v = y.data();
  VectorX below(m.widest_below);
  for (int s = 0; s < m.nsuper; ++s) {  // L y = P b
    const int k1 = m.super[s], ncol = m.super[s + 1] - k1, nrow = m.pi[s + 1] - m.pi[s];
    const int nbelow = nrow - ncol;
    const int* r = m.rows.data() + m.pi[s] + ncol;
    const double* L = m.values.data() + m.px[s];
    auto update = below.head(nbelow);
    update.setZero();
    for (int j = 0; j < ncol; ++j) {
      const double* column = L + static_cast<Index>(j) * nrow;
      const double x = m.ldlt ? v[k1 + j] : (v[k1 + j] /= column[j]);
      for (int i = j + 1; i < ncol; ++i) v[k1 + i] -= column[i] * x;
      update.noalias() += x * Column(column + ncol, nbelow);
    }
    for (int i = 0; i < nbelow; ++i) v[r[i]] -= update[i];
  }
  if (m.ldlt) {  // D w = y (D on the diagonal of each supernode's block)
    for (int s = 0; s < m.nsuper; ++s) {
      const int nrow = m.pi[s + 1] - m.pi[s];
      const double* L = m.values.data() + m.px[s];
      for (int k = m.super[s]; k < m.super[s + 1]; ++k) {
        v[k] /= L[static_cast<Index>(k - m.super[s]) * (nrow + 1)];
      }
    }
  }
  for (int s = m.nsuper - 1; s >= 0; --s) {  // L^T z = y
    const int k1 = m.super[s], ncol = m.super[s + 1] - k1, nrow = m.pi[s + 1] - m.pi[s];
    const int nbelow = nrow - ncol;
    const int* r = m.rows.data() + m.pi[s] + ncol;
    const double* L = m.values.data() + m.px[s];
    auto solved = below.head(nbelow);
    for (int i = 0; i < nbelow; ++i) solved[i] = v[r[i]];
    for (int j = ncol - 1; j >= 0; --j) {
      const double* column = L + static_cast<Index>(j) * nrow;
      double sum = v[k1 + j] - Column(column + ncol, nbelow).dot(solved);
      for (int i = j + 1; i < ncol; ++i) sum -= column[i] * v[k1 + i];
      v[k1 + j] = m.ldlt ? sum : sum / column[j];
    }
  }
  VectorX x(m.n);
  for (Index k = 0; k < m.n; ++k) x[m.perm[k]] = y[k];
  return x;
}

}  // namespace kresling::solvers
