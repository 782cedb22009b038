// clothbench sweep SCENE [--collider a,b] [--set key=v1,v2]... [--repetitions N] [--end-state] --out DIR
//                  [--jobs N | --shard i/N | --slurm [--partition P] [--time T] [--tasks K] [--no-wait]]
// clothbench merge DIR... --out FILE [--allow-mixed]
// Every point runs in a child process of its own (fork, no exec), so a crash or a bad value fails that
// point only; points already done in DIR are skipped. Exit 5 when a point failed or is missing.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

#include "clothbench/bench/report.hpp"
#include "clothbench/bench/scene.hpp"
#include "clothbench/bench/sweep.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/timer.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

namespace fs = std::filesystem;

struct SweepArgs {
  std::string scene, out, shard, partition, time;
  std::string colliders;
  std::vector<std::string> sets;
  int repetitions = 1, jobs = 0, tasks = 0;
  bool slurm = false, no_wait = false, end_state = false;
};

// the child's work: one point, its failure written where merge finds it
int child_runs(const SweepGrid& grid, const SweepPoint& p, const std::string& dir) {
  try {
    run_point(grid, p, dir);
    return 0;
  } catch (const InputError& e) {
    write_point_error(dir, p, e.what(), 2);
    return 2;
  } catch (const std::exception& e) {
    write_point_error(dir, p, e.what(), 1);
    return 1;
  }
}

// a child that ended without a result and without saying why: crashed or killed
void record_exit(const std::string& dir, const SweepPoint& p, int status) {
  if (fs::exists(point_path(dir, p)) || fs::exists(point_error_path(dir, p))) return;
  const std::string why = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                              : "exited with status " + std::to_string(WEXITSTATUS(status));
  write_point_error(dir, p, why + " without a result", WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status));
}

// runs the points in at most `jobs` child processes at once, with progress; returns how many failed
int run_pool(const SweepGrid& grid, const std::vector<SweepPoint>& points, int jobs, const std::string& dir) {
  int done = 0, failed = 0;
  Stopwatch clock;
  run_children(
      points.size(), jobs, [&](std::size_t k) { return child_runs(grid, points[k], dir); },
      [&](std::size_t k, int status) {
        record_exit(dir, points[k], status);
        const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
        failed += !ok;
        ++done;
        const double s = clock.ms() / 1e3;
        std::cerr << "[sweep] " << done << " of " << points.size() << " points done"
                  << (failed ? " (" + std::to_string(failed) + " failed)" : "") << ", " << num(s, 1) << " s, ETA "
                  << num(s / done * double(points.size() - std::size_t(done)), 1) << " s"
                  << (ok ? "" : "; failed: " + points[k].name) << "\n";
      });
  return failed;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// what a shard of this grid runs, as arguments of `clothbench sweep`
std::string grid_arguments(const SweepGrid& g, const std::string& dir) {
  std::string a = shell_quote(g.scene);
  if (!g.colliders.empty()) {
    std::string list;
    for (const auto& c : g.colliders) list += (list.empty() ? "" : ",") + c;
    a += " --collider " + shell_quote(list);
  }
  for (const auto& axis : g.axes) {
    std::string values;
    for (const auto& v : axis.values) values += (values.empty() ? "" : ",") + v;
    a += " --set " + shell_quote(axis.key + "=" + values);
  }
  return a + " --repetitions " + std::to_string(g.repetitions) + (g.end_state ? " --end-state" : "") + " --out " +
         shell_quote(fs::absolute(dir).string());
}

// a command's output; a failing command is an error quoting it
std::string checked_output(const std::string& cmd) {
  int status = 0;
  const std::string out = command_output(cmd, &status);
  if (status != 0) throw std::runtime_error("`" + cmd + "` failed: " + out);
  return out;
}

int merge_into(const std::vector<std::string>& dirs, const std::string& out, bool allow_mixed);

// writes DIR/sweep.sbatch (an array of `tasks` shards), submits it, waits for it and merges
int run_slurm(const SweepArgs& a, const SweepGrid& grid, std::size_t points) {
  const int tasks = static_cast<int>(std::min<std::size_t>(a.tasks > 0 ? std::size_t(a.tasks) : points, points));
  const std::string script = (fs::path(a.out) / "sweep.sbatch").string();
  std::ostringstream s;
  s << "#!/bin/sh\n#SBATCH --job-name=clothbench-sweep\n#SBATCH --array=0-" << tasks - 1 << "\n#SBATCH --output="
    << fs::absolute(a.out).string() << "/slurm-%A_%a.out\n#SBATCH --cpus-per-task=1\n";
  if (!a.partition.empty()) s << "#SBATCH --partition=" << a.partition << "\n";
  if (!a.time.empty()) s << "#SBATCH --time=" << a.time << "\n";
  s << "exec " << shell_quote(fs::canonical("/proc/self/exe").string()) << " sweep " << grid_arguments(grid, a.out)
    << " --jobs 1 --shard \"$SLURM_ARRAY_TASK_ID/" << tasks << "\"\n";
  write_text_file(script, s.str());
  const std::string reply = checked_output("sbatch --parsable " + shell_quote(script) + " 2>&1");
  const std::string job = reply.substr(0, reply.find_first_of(";\n"));
  std::cerr << "[sweep] submitted Slurm job " << job << ": " << tasks << " array tasks for " << points << " points ("
            << script << ")\n";
  const std::string merged = (fs::path(a.out) / "merged.json").string();
  if (a.no_wait) {
    std::cerr << "[sweep] not waiting; when it is done: clothbench merge " << a.out << " --out " << merged << "\n";
    return 0;
  }
  while (!checked_output("squeue -h -j " + job + " -o %i 2>/dev/null || true").empty())
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  return merge_into({a.out}, merged, false);
}

int sweep(const SweepArgs& a) {
  SweepGrid grid;
  grid.scene = fs::absolute(a.scene).lexically_normal().string();  // shards may start elsewhere
  grid.repetitions = a.repetitions;
  grid.end_state = a.end_state;
  if (!a.colliders.empty()) grid.colliders = parse_axis("collider=" + a.colliders).values;
  for (const auto& s : a.sets) grid.axes.push_back(parse_axis(s));
  load_scene(grid.scene);  // a bad scene file fails the sweep, a bad value only its points
  claim_folder(a.out, grid);
  const std::vector<SweepPoint> all = expand_grid(grid);
  if (a.slurm) return run_slurm(a, grid, all.size());
  std::vector<SweepPoint> todo;
  const auto [shard, shards] = a.shard.empty() ? std::pair{0, 1} : parse_shard(a.shard);
  for (const SweepPoint& p : shard_points(all, shard, shards))
    if (!point_done(a.out, p)) todo.push_back(p);
  const int jobs = a.jobs > 0 ? a.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::cerr << "[sweep] " << all.size() << " points" << (a.shard.empty() ? "" : ", shard " + a.shard) << ": "
            << todo.size() << " to run, " << jobs << " at a time\n";
  const int failed = run_pool(grid, todo, jobs, a.out);
  if (!a.shard.empty()) return failed ? 5 : 0;
  return merge_into({a.out}, (fs::path(a.out) / "merged.json").string(), false);
}

int merge_into(const std::vector<std::string>& dirs, const std::string& out, bool allow_mixed) {
  const nlohmann::json doc = merge_sweeps(dirs, allow_mixed);
  write_text_file(out, doc.dump(1) + "\n");
  std::printf("merged %zu rows into %s; %zu point(s) failed or missing\n", doc["benchmarks"].size(), out.c_str(),
              doc["failed"].size());
  for (const auto& f : doc["failed"])
    std::printf("  FAILED %s (point %d of %s, exit status %d): %s\n", f.value("name", "?").c_str(), f.value("index", -1),
                f.value("folder", "?").c_str(), f.value("exit_status", -1), f.value("error", "?").c_str());
  return doc["failed"].empty() ? 0 : 5;
}

}  // namespace

void add_sweep_command(CLI::App& app, Action& action) {
  auto a = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand("sweep",
                                 "Run a grid of scene runs (colliders x --set values) in worker processes, one shard of "
                                 "it, or as a Slurm job array; DIR/merged.json joins them. Exit 5 when a point failed");
  cmd->add_option("scene", a->scene, "scene file (TOML)")->required();
  cmd->add_option("--collider", a->colliders, "comma-separated colliders (default: the scene's)");
  cmd->add_option("--set", a->sets, "section.key=v1,v2,...: an axis of the grid (repeatable)");
  cmd->add_option("--repetitions", a->repetitions, "runs per point")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--out", a->out, "the sweep's folder (points/, sweep.json, merged.json)")->required();
  cmd->add_flag("--end-state", a->end_state,
                "keep each run's cloth at its end in its row, so that `report --reference` measures the drape error");
  cmd->add_option("--jobs", a->jobs, "worker processes at once (default: the cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--shard", a->shard, "i/N: run only points i, i + N, ... (for any scheduler)");
  cmd->add_flag("--slurm", a->slurm, "submit an sbatch job array (task k runs shard k), wait, merge");
  cmd->add_option("--partition", a->partition, "--slurm: the partition");
  cmd->add_option("--time", a->time, "--slurm: the time limit of each task (sbatch --time)");
  cmd->add_option("--tasks", a->tasks, "--slurm: array tasks (default: one per point)")->check(CLI::Range(1, 100000));
  cmd->add_flag("--no-wait", a->no_wait, "--slurm: submit and return (merge later)");
  cmd->callback([&action, a] { action = [a] { return sweep(*a); }; });

  auto dirs = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  auto mixed = std::make_shared<bool>(false);
  auto* merge = app.add_subcommand("merge", "Join sweep folders into one Google Benchmark JSON; exit 5 when a point "
                                            "failed or is missing (listed)");
  merge->add_option("dirs", *dirs, "sweep folders")->required();
  merge->add_option("--out", *out, "the merged JSON")->required();
  merge->add_flag("--allow-mixed", *mixed, "join points of different builds (git SHA, compiler, flags)");
  merge->callback([&action, dirs, out, mixed] { action = [=] { return merge_into(*dirs, *out, *mixed); }; });
}

}  // namespace clothbench::cli
