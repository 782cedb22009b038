#pragma once
/// `clothbench sweep`: a grid of independent runs (colliders x the values of each `--set` key), each
/// point named by its settings and written to DIR/points/INDEX.json (or INDEX.error.json when it failed),
/// so shards run anywhere (locally in worker processes, as a Slurm job array) and `merge` joins them.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace clothbench {

/// One swept key and its values: `--set key=v1,v2` (commas inside [...] or quotes stay in the value).
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};
SweepAxis parse_axis(const std::string& arg);

/// The grid: a scene file, its colliders and axes, repetitions per point.
struct SweepGrid {
  std::string scene;                   ///< scene file as given
  std::vector<std::string> colliders;  ///< empty: the scene's own
  std::vector<SweepAxis> axes;
  int repetitions = 1;
  bool end_state = false;  ///< every run's row carries the cloth's end state (report --reference)
  nlohmann::json to_json() const;
  static SweepGrid from_json(const nlohmann::json& j);
};

/// One point of the grid, in grid order (colliders outermost, then the axes in the order given).
struct SweepPoint {
  int index = 0;
  std::string collider;           ///< empty: the scene's own
  std::vector<std::string> sets;  ///< key=value overrides
  std::string name;               ///< "collider/key=value/...", unique within the grid
};
std::vector<SweepPoint> expand_grid(const SweepGrid& grid);

/// "i/N" with 0 <= i < N; InputError otherwise.
std::pair<int, int> parse_shard(const std::string& text);
/// The points of shard i of n: indices i, i + n, i + 2n, ...
std::vector<SweepPoint> shard_points(const std::vector<SweepPoint>& all, int i, int n);

/// DIR/points/INDEX.json and INDEX.error.json.
std::string point_path(const std::string& dir, const SweepPoint& p);
std::string point_error_path(const std::string& dir, const SweepPoint& p);
/// The point's result exists and is this point's (a result of another grid there is an InputError).
bool point_done(const std::string& dir, const SweepPoint& p);

/// Runs child(0 .. count-1), each in a forked process of its own (no exec), at most `jobs` at once;
/// done(k, status) gets each one's waitpid status as it ends, in the order they end. Fork before any
/// thread or GL context exists in the parent.
void run_children(std::size_t count, int jobs, const std::function<int(std::size_t)>& child,
                  const std::function<void(std::size_t, int)>& done);

/// Runs one point (its repetitions) and writes its result document; throws what the run throws.
void run_point(const SweepGrid& grid, const SweepPoint& p, const std::string& dir);
/// Writes the point's failure: its error text and the exit status of the process that ran it.
void write_point_error(const std::string& dir, const SweepPoint& p, const std::string& error, int exit_status);

/// DIR/sweep.json: the grid a folder belongs to. Written once; a folder of another grid is an InputError.
void claim_folder(const std::string& dir, const SweepGrid& grid);

/// Joins the points of sweep folders into one Google Benchmark document: every point's rows, and under
/// "failed" every point that failed (its error and exit status) or never ran ("missing"). Points of
/// different builds (git SHA, compiler, flags, build type) are refused unless `allow_mixed`.
nlohmann::json merge_sweeps(const std::vector<std::string>& dirs, bool allow_mixed);

}  // namespace clothbench
