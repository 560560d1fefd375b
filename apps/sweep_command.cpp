#include "sweep_command.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <thread>

#include "sluice/core/errors.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/sweep_plan.hpp"
#include "sluice/io/sweep_table.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "sluice/sim/runner.hpp"

extern char** environ;

namespace sluice {

namespace {

struct RunningJob {
  std::size_t run = 0;
  std::chrono::steady_clock::time_point start;
};

// Starts args[0] with args; with `log`, its stdout and stderr go to that file. Throws
// std::runtime_error when it cannot start.
pid_t spawn(std::vector<std::string> args, const std::string& log = "") {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  if (!log.empty()) {
    posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
  }
  pid_t pid = 0;
  const int failed = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (failed != 0) throw std::runtime_error("cannot start " + args[0] + ": " + strerror(failed));
  return pid;
}

// Starts `sluice run` for one combination with its output in `dir`, its messages in dir.log.
pid_t start_run(const SweepOptions& o, const io::SweepRun& run, const std::string& dir,
                int threads) {
  std::vector<std::string> args{o.self,
                                "run",
                                o.case_path,
                                "--out",
                                dir,
                                "--threads",
                                std::to_string(threads),
                                "--stats",
                                dir + "/stats.json"};
  if (o.end_time > 0) {
    args.push_back("--end");
    args.push_back(fmt::format("{}", o.end_time));
  }
  for (const std::string& s : run.overrides) {
    args.push_back("--set");
    args.push_back(s);
  }
  return spawn(std::move(args), dir + ".log");
}

std::string status_of(int wait_status) {
  if (WIFEXITED(wait_status)) {
    const int code = WEXITSTATUS(wait_status);
    if (code == kExitOk) return "done";
    if (code == kExitDiverged) return "diverged";
    return fmt::format("failed (exit {})", code);
  }
  return "failed (killed)";
}

// Draws the plots with Debian's matplotlib when it is there.
void draw_plots(const std::string& out_dir) {
  const std::string script = std::string(SLUICE_SOURCE_DIR) + "/scripts/plot_sweep.py";
  const std::string python = "/usr/bin/python3";
  if (access(script.c_str(), R_OK) != 0 || access(python.c_str(), X_OK) != 0) {
    fmt::print("plots: not drawn ({} or {} missing)\n", python, script);
    return;
  }
  int status = 0;
  if (waitpid(spawn({python, script, out_dir}), &status, 0) < 0 || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    fmt::print("plots: {} {} {} failed\n", python, script, out_dir);
  }
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  std::vector<io::SweepSetting> settings;
  for (const std::string& s : o.settings) settings.push_back(io::parse_sweep_setting(s));
  const std::vector<io::SweepRun> runs = io::sweep_runs(settings);
  const std::vector<std::string> keys = io::sweep_axes(settings);
  // Every combination is read and built (the model checks its own keys) before anything runs
  // or is written, as `sluice check` would.
  std::string name;
  for (const io::SweepRun& run : runs) {
    const io::CaseConfig config = io::read_case(o.case_path, run.overrides);
    check_case(config);
    name = config.name;
  }
  const std::string out_dir = o.out_dir.empty() ? "out/sweep_" + name : o.out_dir;
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) {
    throw InputError(out_dir + ": cannot create the output directory: " + error.message());
  }

  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int jobs = std::clamp(o.jobs > 0 ? o.jobs : cores, 1, static_cast<int>(runs.size()));
  const int threads = std::max(1, cores / jobs);
  fmt::print("sweep: {} runs of {} ({} at once, {} thread{} each) in {}\n", runs.size(),
             o.case_path, jobs, threads, threads > 1 ? "s" : "", out_dir);

  std::vector<io::SweepResult> results(runs.size());
  std::map<pid_t, RunningJob> running;
  std::size_t next = 0, finished = 0;
  const auto dir_of = [&](std::size_t k) { return fmt::format("{}/run_{:03d}", out_dir, k + 1); };
  while (finished < runs.size()) {
    while (next < runs.size() && static_cast<int>(running.size()) < jobs) {
      const pid_t pid = start_run(o, runs[next], dir_of(next), threads);
      running[pid] = RunningJob{next, std::chrono::steady_clock::now()};
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0 && errno != EINTR) {
      throw std::runtime_error(std::string("waiting for the runs: ") + strerror(errno));
    }
    const auto job = running.find(pid);
    if (job == running.end()) continue;  // interrupted, or not one of ours
    const std::size_t k = job->second.run;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - job->second.start).count();
    running.erase(job);
    ++finished;
    io::SweepResult& r = results[k];
    r.values = runs[k].values;
    r.status = status_of(status);
    if (r.status == "done") r.measurements = io::read_run_measurements(dir_of(k) + "/stats.json");
    std::string label;
    for (std::size_t a = 0; a < keys.size(); ++a)
      label += fmt::format("{}{}={}", a ? " " : "", keys[a], r.values[a]);
    fmt::print("[{}/{}] run_{:03d} {}: {} in {:.1f} s{}\n", finished, runs.size(), k + 1, label,
               r.status, seconds, r.status == "done" ? "" : " (see " + dir_of(k) + ".log)");
    std::fflush(stdout);
  }
  io::write_file_atomically(out_dir + "/summary.csv", io::sweep_table_csv(keys, results));
  io::write_file_atomically(out_dir + "/summary.md", io::sweep_table_markdown(keys, results));
  fmt::print("summary: {0}/summary.csv, {0}/summary.md\n", out_dir);
  std::fflush(stdout);
  draw_plots(out_dir);
  const bool all_done = std::all_of(results.begin(), results.end(),
                                    [](const io::SweepResult& r) { return r.status == "done"; });
  return all_done ? kExitOk : kExitDiverged;
}

}  // namespace sluice
