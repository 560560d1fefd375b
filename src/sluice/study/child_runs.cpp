#include "sluice/study/child_runs.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <thread>

#include "sluice/core/errors.hpp"

extern char** environ;

namespace sluice {

namespace {

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

std::string status_of(int wait_status) {
  if (WIFEXITED(wait_status)) {
    const int code = WEXITSTATUS(wait_status);
    if (code == kExitOk) return "done";
    if (code == kExitDiverged) return "diverged";
    return fmt::format("failed (exit {})", code);
  }
  return "failed (killed)";
}

struct RunningJob {
  std::size_t run = 0;
  std::chrono::steady_clock::time_point start;
};

}  // namespace

void create_study_directory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw InputError(dir + ": cannot create the output directory: " + error.message());
}

void report_study_start(const StudyOptions& options, const std::string& head, int jobs, int threads,
                        const std::string& out_dir) {
  if (!options.report) return;
  fmt::print("{} ({} at once, {} thread{} each) in {}\n", head, jobs, threads,
             threads > 1 ? "s" : "", out_dir);
  std::fflush(stdout);
}

void report_run_end(const StudyOptions& options, std::size_t finished, std::size_t total,
                    const std::string& label, const std::string& status, double seconds,
                    const std::string& run_dir) {
  if (!options.report) return;
  fmt::print("[{}/{}] {}: {} in {:.1f} s{}\n", finished, total, label, status, seconds,
             status == "done" ? "" : " (see " + run_dir + ".log)");
  std::fflush(stdout);
}

ChildRun sluice_run(const std::string& program, const std::string& case_path,
                    const std::string& dir, int threads, double end_time,
                    const std::vector<std::string>& overrides) {
  std::vector<std::string> args{program,
                                "run",
                                case_path,
                                "--out",
                                dir,
                                "--threads",
                                std::to_string(threads),
                                "--stats",
                                dir + "/stats.json"};
  if (end_time > 0) {
    args.push_back("--end");
    args.push_back(fmt::format("{}", end_time));
  }
  for (const std::string& s : overrides) {
    args.push_back("--set");
    args.push_back(s);
  }
  return {std::move(args), dir + ".log"};
}

std::vector<ChildOutcome> run_children(
    const std::vector<ChildRun>& runs, int jobs,
    const std::function<void(std::size_t, const ChildOutcome&)>& finished,
    const std::function<bool()>& stop_requested) {
  std::vector<ChildOutcome> outcomes(runs.size());
  std::map<pid_t, RunningJob> running;
  // A run that cannot start, a row that cannot be read or a stop: the runs still going are
  // stopped and waited for, none left behind writing into the study's folder.
  struct StopTheRest {
    std::map<pid_t, RunningJob>& running;
    ~StopTheRest() {
      for (const auto& job : running) kill(job.first, SIGTERM);
      for (const auto& job : running) waitpid(job.first, nullptr, 0);
    }
  } stop_the_rest{running};
  std::size_t next = 0, done = 0;
  while (done < runs.size()) {
    while (next < runs.size() && static_cast<int>(running.size()) < jobs) {
      const pid_t pid = spawn(runs[next].args, runs[next].log);
      running[pid] = RunningJob{next, std::chrono::steady_clock::now()};
      ++next;
    }
    // Each of its own children in turn, without blocking: waitpid(-1) would also take the exit
    // of a child the caller started itself (a Python script's subprocess).
    bool any_ended = false;
    for (auto job = running.begin(); job != running.end();) {
      int status = 0;
      const pid_t ended = waitpid(job->first, &status, WNOHANG);
      if (ended < 0 && errno != EINTR) {
        throw std::runtime_error(std::string("waiting for the runs: ") + strerror(errno));
      }
      if (ended != job->first) {
        ++job;
        continue;
      }
      const std::size_t k = job->second.run;
      outcomes[k].seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - job->second.start)
              .count();
      outcomes[k].status = status_of(status);
      job = running.erase(job);
      ++done;
      any_ended = true;
      finished(k, outcomes[k]);
    }
    if (stop_requested && stop_requested()) throw StudyStopped();
    if (!any_ended && done < runs.size()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  return outcomes;
}

int threads_per_run(int jobs) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / std::max(1, jobs));
}

std::string this_program() {
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof(self) - 1);
  if (length <= 0) return "/proc/self/exe";
  return std::string(self, static_cast<std::size_t>(length));
}

std::optional<int> run_script(const std::string& script, const std::vector<std::string>& args,
                              const std::string& log) {
  const std::string path = std::string(SLUICE_SOURCE_DIR) + "/scripts/" + script;
  const std::string python = "/usr/bin/python3";
  if (access(path.c_str(), R_OK) != 0 || access(python.c_str(), X_OK) != 0) return std::nullopt;
  std::vector<std::string> command{python, path};
  command.insert(command.end(), args.begin(), args.end());
  int status = 0;
  if (waitpid(spawn(command, log), &status, 0) < 0 || !WIFEXITED(status)) return std::nullopt;
  return WEXITSTATUS(status);
}

void draw_plots(const std::string& script, const std::vector<std::string>& args, bool report) {
  const std::optional<int> code = run_script(script, args, report ? "" : "/dev/null");
  if (!report) return;
  if (!code) {
    fmt::print("plots: not drawn (/usr/bin/python3 or scripts/{} missing, or it was stopped)\n",
               script);
  } else if (*code != 0) {
    fmt::print("plots: scripts/{} failed\n", script);
  }
}

}  // namespace sluice
