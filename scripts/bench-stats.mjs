// The statistics the benchmarks quote: medians, percentiles, and figures rounded to 0.01.

/** Median of `xs` (null when empty). */
export const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length ? (s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2) : null;
};

/** The `p`th percentile of `xs` (nearest rank; null when empty). */
export const percentile = (xs, p) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.min(s.length - 1, Math.ceil((p / 100) * s.length) - 1)] : null;
};

/** `x` rounded to hundredths (null stays null). */
export const round = (x) => (x === null ? null : Math.round(x * 100) / 100);
