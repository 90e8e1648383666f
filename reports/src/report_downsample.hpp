// Down-sampling of long time series for embedding in a report: every sample
// inside a contact window is kept (the pulses are what a reader zooms into),
// the smooth stretches between them are thinned evenly.
#pragma once

#include <cstddef>
#include <vector>

namespace pb::internal {

struct TimeWindow {
  double t0_s = 0.0;  // s
  double t1_s = 0.0;  // s, >= t0_s
};

// Sorts the windows and merges those that overlap or touch.
[[nodiscard]] std::vector<TimeWindow> merge_windows(std::vector<TimeWindow> windows);

// Indices (ascending) of the samples of `time_s` (ascending) to keep: the
// first and the last sample, every sample inside a window of `windows`
// (merged) but at most about `max_inside` of them, and at most `max_outside`
// of the samples outside the windows, evenly strided. Beyond `max_inside`
// (a sustained contact), the inside samples are thinned evenly, or, given
// `value` (same length as `time_s`), by keeping the lowest and the highest
// sample of each run of consecutive inside samples, so that peaks survive.
[[nodiscard]] std::vector<std::size_t> downsample_indices(const std::vector<double>& time_s,
                                                          const std::vector<TimeWindow>& windows,
                                                          std::size_t max_outside,
                                                          std::size_t max_inside,
                                                          const std::vector<double>* value = nullptr);

// Indices (ascending) of a min-max decimation of the samples with t in
// [t0_s, t1_s] into `buckets` equal time buckets: per bucket its first, lowest,
// highest and last sample, so peaks survive (for static figures). The sample
// just outside each end of the range is kept too, so lines reach the frame.
[[nodiscard]] std::vector<std::size_t> minmax_indices(const std::vector<double>& time_s,
                                                      const std::vector<double>& value, double t0_s,
                                                      double t1_s, std::size_t buckets);

}  // namespace pb::internal
