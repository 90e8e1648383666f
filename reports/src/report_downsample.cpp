#include "report_downsample.hpp"

#include <algorithm>
#include <cmath>

namespace pb::internal {

std::vector<TimeWindow> merge_windows(std::vector<TimeWindow> windows) {
  std::sort(windows.begin(), windows.end(),
            [](const TimeWindow& a, const TimeWindow& b) { return a.t0_s < b.t0_s; });
  std::vector<TimeWindow> merged;
  for (const auto& w : windows) {
    if (!(w.t1_s >= w.t0_s)) continue;  // empty or NaN
    if (!merged.empty() && w.t0_s <= merged.back().t1_s) {
      merged.back().t1_s = std::max(merged.back().t1_s, w.t1_s);
    } else {
      merged.push_back(w);
    }
  }
  return merged;
}

std::vector<std::size_t> downsample_indices(const std::vector<double>& time_s,
                                            const std::vector<TimeWindow>& windows,
                                            std::size_t max_outside, std::size_t max_inside,
                                            const std::vector<double>* value) {
  const std::size_t n = time_s.size();
  if (n == 0) return {};
  const auto merged = merge_windows(windows);

  // mark each sample inside or outside the windows (both ascending: one pass)
  std::vector<char> inside(n, 0);
  std::size_t w = 0;
  std::size_t n_inside = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (w < merged.size() && merged[w].t1_s < time_s[i]) ++w;
    if (w < merged.size() && time_s[i] >= merged[w].t0_s) {
      inside[i] = 1;
      ++n_inside;
    }
  }
  const std::size_t n_outside = n - n_inside;

  // strides so that each class stays within its budget
  auto stride_for = [](std::size_t count, std::size_t budget) -> std::size_t {
    if (budget < 2 || count <= budget) return 1;
    return (count + budget - 2) / (budget - 1);
  };
  const std::size_t stride_out = stride_for(n_outside, std::max<std::size_t>(max_outside, 2));
  const std::size_t stride_in = stride_for(n_inside, std::max<std::size_t>(max_inside, 2));

  // inside, thinned with values: per block of 2 * stride_in consecutive
  // inside samples its lowest and its highest (NaN samples never chosen)
  const bool extremes = value != nullptr && value->size() == n && stride_in > 1;
  std::vector<char> extreme(extremes ? n : 0, 0);
  if (extremes) {
    const std::size_t block = 2 * stride_in;
    std::size_t count = 0;
    std::size_t lo = n;
    std::size_t hi = n;
    auto close_block = [&] {
      if (lo < n) extreme[lo] = 1;
      if (hi < n) extreme[hi] = 1;
      count = 0;
      lo = hi = n;
    };
    for (std::size_t i = 0; i < n; ++i) {
      if (inside[i] == 0) continue;
      const double v = (*value)[i];
      if (!std::isnan(v)) {
        if (lo == n || v < (*value)[lo]) lo = i;
        if (hi == n || v > (*value)[hi]) hi = i;
      }
      if (++count == block) close_block();
    }
    close_block();
  }

  std::vector<std::size_t> keep;
  std::size_t ordinal_in = 0;
  std::size_t ordinal_out = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool first_or_last = i == 0 || i + 1 == n;
    bool take = false;
    if (inside[i] != 0) {
      take = extremes ? extreme[i] != 0 || ordinal_in == 0 || ordinal_in + 1 == n_inside
                      : ordinal_in % stride_in == 0 || ordinal_in + 1 == n_inside;
      ++ordinal_in;
    } else {
      take = ordinal_out % stride_out == 0 || ordinal_out + 1 == n_outside;
      ++ordinal_out;
    }
    if (take || first_or_last) keep.push_back(i);
  }
  return keep;
}

std::vector<std::size_t> minmax_indices(const std::vector<double>& time_s,
                                        const std::vector<double>& value, double t0_s, double t1_s,
                                        std::size_t buckets) {
  const std::size_t n = std::min(time_s.size(), value.size());
  std::vector<std::size_t> keep;
  if (n == 0 || !(t1_s > t0_s) || buckets == 0) return keep;
  const auto begin = static_cast<std::size_t>(
      std::lower_bound(time_s.begin(), time_s.begin() + static_cast<std::ptrdiff_t>(n), t0_s) -
      time_s.begin());
  const auto end = static_cast<std::size_t>(
      std::upper_bound(time_s.begin(), time_s.begin() + static_cast<std::ptrdiff_t>(n), t1_s) -
      time_s.begin());
  if (begin > 0) keep.push_back(begin - 1);

  // per bucket: first, min, max, last (NaN samples are skipped)
  const double width = (t1_s - t0_s) / static_cast<double>(buckets);
  std::size_t i = begin;
  while (i < end) {
    const auto b = static_cast<std::size_t>(
        std::min(static_cast<double>(buckets - 1), std::floor((time_s[i] - t0_s) / width)));
    const double bucket_end = t0_s + width * static_cast<double>(b + 1);
    std::size_t first = i;
    std::size_t last = i;
    std::size_t lo = i;
    std::size_t hi = i;
    // the bucket's first sample always advances i, whatever the rounding of bucket_end
    for (; i < end && (i == first || time_s[i] < bucket_end || b + 1 == buckets); ++i) {
      last = i;
      if (std::isnan(value[i])) continue;
      if (std::isnan(value[lo]) || value[i] < value[lo]) lo = i;
      if (std::isnan(value[hi]) || value[i] > value[hi]) hi = i;
    }
    std::size_t four[] = {first, lo, hi, last};
    std::sort(std::begin(four), std::end(four));
    for (const std::size_t k : four) {
      if (keep.empty() || keep.back() != k) keep.push_back(k);
    }
  }
  if (end < n) keep.push_back(end);
  return keep;
}

}  // namespace pb::internal
