// The Vulkan path's fixed cost (issue 15): README's command 1 (the teapot in the default mode,
// rule T at 0.1% of the diagonal) and the teapot by rule B, on Vulkan and on the CPU backend,
// in process (context + backend + tessellate, each run from scratch) and as whole `tessera
// tessellate` processes, warm (Mesa's shader cache and the pipeline cache as a second run finds
// them) and cold (both off). Prints where the Vulkan time goes (vk::ContextTimings: instance,
// device, pipeline cache, pipelines, first dispatch, dispatches) and the Vulkan/CPU ratios,
// minima and medians over the runs. Whole processes are timed by wall clock and by their CPU time
// (user + sys of all their threads), which a loaded machine moves much less.
//   bench_startup [runs]   (default 9; at least 5; per job and backend)
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_args.h"
#include "bench_report.h"
#include "io/bpt_reader.h"
#include "mesh/tessellate.h"
#include "quadtree/tolerance.h"
#include "vk/context.h"

extern char** environ;

namespace tessera {
namespace {

struct Series {
  std::vector<double> ms;
  void add(double v) { ms.push_back(v); }
  double min() const { return *std::min_element(ms.begin(), ms.end()); }
  double median() const {
    std::vector<double> s = ms;
    std::sort(s.begin(), s.end());
    return s[s.size() / 2];
  }
};

bench::Case toCase(const std::string& path, const Series& s) {
  bench::Case c{path, 1};
  c.timing = {s.min() / 1e3, s.median() / 1e3, int(s.ms.size())};
  return c;
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

struct ProcessTimes {
  double wallMs = 0;
  double cpuMs = 0;  // user + sys, all threads
};

// One `tessera tessellate` process with `extraEnv` added; its times. Throws when it cannot
// start or fails.
ProcessTimes runProcess(const std::vector<std::string>& args,
                        const std::vector<std::string>& extraEnv) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<std::string> envStrings(extraEnv);
  for (char** e = environ; *e; ++e) envStrings.emplace_back(*e);  // extraEnv first: it wins
  std::vector<char*> envp;
  for (const std::string& e : envStrings) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  // The summary a run without -q prints (as README's command 1 does) goes to /dev/null.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  const Stopwatch stopwatch;
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start " + args[0]);
  int status = 0;
  struct rusage usage {};
  wait4(pid, &status, 0, &usage);
  const double ms = stopwatch.elapsedMs();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(args[0] + " failed (status " + std::to_string(status) + ")");
  const auto toMs = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec * 1e-3; };
  return {ms, toMs(usage.ru_utime) + toMs(usage.ru_stime)};
}


// One job: its name, its options in process and its extra arguments on the command line.
struct Job {
  const char* name;
  QuadtreeOptions options;
  std::vector<std::string> cliArgs;
};

// In process, every run from scratch: what one CLI run pays besides process start.
// `nameDevice`: the first job names the device in the report.
void inProcess(bench::Report& report, const std::vector<BezierPatch>& teapot, const Job& job,
               int runs, bool nameDevice) {
  Series cpu, vulkan, instance, device, cache, pipelines, firstSubmit, submits, tree;
  size_t triangles = 0;
  std::string deviceName;
  for (int r = 0; r <= runs; ++r) {  // run 0 warms the caches and is not counted
    Stopwatch stopwatch;
    Backend mirror = makeMirrorBackend();
    Tessellation c = tessellate(teapot, job.options, mirror);
    const double cpuMs = stopwatch.elapsedMs();
    stopwatch.restart();
    vk::Context context;
    Tessellation v;
    {
      Backend backend = makeVulkanBackend(context);
      v = tessellate(teapot, job.options, backend);
    }
    const double vulkanMs = stopwatch.elapsedMs();
    if (v.mesh.positions != c.mesh.positions || v.mesh.indices != c.mesh.indices)
      throw std::runtime_error(std::string("the Vulkan mesh differs from the CPU one: ") + job.name);
    triangles = v.mesh.triangleCount();
    deviceName = context.info().name;
    if (r == 0) {
      if (nameDevice) report.setDevice(context);
      continue;
    }
    const vk::ContextTimings t = context.timings();
    cpu.add(cpuMs);
    vulkan.add(vulkanMs);
    instance.add(t.instanceMs);
    device.add(t.deviceMs);
    cache.add(t.pipelineCacheMs);
    pipelines.add(t.pipelinesMs);
    firstSubmit.add(t.firstSubmitMs);
    submits.add(t.submitsMs);
    tree.add(v.stats.treeMs);
  }
  // Milliseconds, so printed by hand: the report's tables are for throughputs.
  std::printf("### teapot %s on %s (%zu triangles), in process, %d runs: ms\n\n", job.name,
              deviceName.c_str(), triangles, runs);
  std::printf("| part | min | median |\n|---|---|---|\n");
  const std::vector<std::pair<const char*, const Series*>> parts = {
      {"CPU backend: backend + tessellate", &cpu},
      {"Vulkan: context + backend + tessellate", &vulkan},
      {"- instance (loader, drivers)", &instance},
      {"- device", &device},
      {"- pipeline cache load", &cache},
      {"- pipelines (driver compiles; summed over threads)", &pipelines},
      {"- first dispatch", &firstSubmit},
      {"- all dispatches (one per level + evaluation)", &submits},
      {"- tessellate's tree stage (treeMs)", &tree}};
  nlohmann::json breakdown = nlohmann::json::object();
  for (const auto& [name, series] : parts) {
    std::printf("| %s | %.1f | %.1f |\n", name, series->min(), series->median());
    breakdown[name] = {{"minMs", series->min()}, {"medianMs", series->median()}};
  }
  std::printf("\nVulkan / CPU, in process: %.2f× by minima, %.2f× by medians\n\n",
              vulkan.min() / cpu.min(), vulkan.median() / cpu.median());
  report.note(std::string("inProcessMs ") + job.name, breakdown);
}

#ifdef TESSERA_CLI_PATH
// Whole processes, as a user runs the job; the summary goes to /dev/null.
void wholeProcess(bench::Report& report, const Job& job, int runs) {
  const std::string out = "/tmp/bench_startup_" + std::to_string(::getpid()) + ".obj";
  auto command = [&](const char* backend) {
    std::vector<std::string> args{TESSERA_CLI_PATH, "tessellate", TESSERA_BENCH_DATA "/teapot.bpt"};
    args.insert(args.end(), job.cliArgs.begin(), job.cliArgs.end());
    args.insert(args.end(), {"--backend", backend, "-o", out});
    return args;
  };
  const std::vector<std::string> cold = {"MESA_SHADER_CACHE_DISABLE=true",
                                         "TESSERA_PIPELINE_CACHE=off"};
  Series cpuProcess, vulkanProcess, coldProcess, cpuCpu, vulkanCpu, coldCpu;
  runProcess(command("vulkan"), {});  // warms Mesa's shader cache and the pipeline cache
  runProcess(command("cpu"), {});
  const auto add = [](const ProcessTimes& t, Series& wall, Series& cpu) {
    wall.add(t.wallMs);
    cpu.add(t.cpuMs);
  };
  for (int r = 0; r < runs; ++r) {
    add(runProcess(command("cpu"), {}), cpuProcess, cpuCpu);
    add(runProcess(command("vulkan"), {}), vulkanProcess, vulkanCpu);
    add(runProcess(command("vulkan"), cold), coldProcess, coldCpu);
  }
  std::remove(out.c_str());
  std::string line = "`tessera tessellate data/teapot.bpt";
  for (const std::string& a : job.cliArgs) line += " " + a;
  bench::Table& processes =
      report.table(std::string("process ") + job.name, "runs",
                   line + " --backend … -o x.obj`, whole process wall time and CPU time (user + "
                          "sys); cold = MESA_SHADER_CACHE_DISABLE=true TESSERA_PIPELINE_CACHE=off");
  processes.cases = {toCase("--backend cpu", cpuProcess),
                     toCase("--backend vulkan, warm caches", vulkanProcess),
                     toCase("--backend vulkan, cold", coldProcess),
                     toCase("CPU time: --backend cpu", cpuCpu),
                     toCase("CPU time: --backend vulkan, warm caches", vulkanCpu),
                     toCase("CPU time: --backend vulkan, cold", coldCpu)};
  report.print(processes);
  std::printf("Vulkan / CPU, whole process, %s: %.2f× by minima, %.2f× by medians (cold: %.2f×, "
              "%.2f×)\n",
              job.name, vulkanProcess.min() / cpuProcess.min(),
              vulkanProcess.median() / cpuProcess.median(), coldProcess.min() / cpuProcess.min(),
              coldProcess.median() / cpuProcess.median());
  std::printf("Vulkan / CPU, process CPU time, %s: %.2f× by minima, %.2f× by medians (cold: "
              "%.2f×, %.2f×)\n\n",
              job.name, vulkanCpu.min() / cpuCpu.min(), vulkanCpu.median() / cpuCpu.median(),
              coldCpu.min() / cpuCpu.min(), coldCpu.median() / cpuCpu.median());
  report.note(std::string("processCpuRatioMin ") + job.name, vulkanCpu.min() / cpuCpu.min());
  report.note(std::string("processCpuRatioMedian ") + job.name,
              vulkanCpu.median() / cpuCpu.median());
  report.note(std::string("processRatioMin ") + job.name, vulkanProcess.min() / cpuProcess.min());
  report.note(std::string("processRatioMedian ") + job.name,
              vulkanProcess.median() / cpuProcess.median());
}
#endif

}  // namespace
}  // namespace tessera

int main(int argc, char** argv) {
  using namespace tessera;
  bench::Report report("bench_startup", "[runs=9, at least 5] [--json file]", argc, argv);
  bench::atMostArguments(report, argc, argv, 1);
  const int runs = std::max(
      bench::kMinRuns, argc > 1 ? int(bench::integerArg(report, argv[1], "runs", 1, 1000)) : 9);
  const auto teapot = readBpt(TESSERA_BENCH_DATA "/teapot.bpt");
  // README's command 1 gives no -m: rule T at the default tolerance, as the CLI resolves it.
  const std::vector<Job> jobs = {
      {"rule T (default, README command 1)",
       toleranceOptions(resolveTolerance(ToleranceSpec{}, teapot)),
       {}},
      {"rule B", QuadtreeOptions{}, {"-m", "B"}}};
  const std::string loadAtStart = loadAverage();
  report.note("loadAverageAtStart", loadAtStart);
  try {
    for (const Job& job : jobs) {
      inProcess(report, teapot, job, runs, &job == &jobs.front());
#ifdef TESSERA_CLI_PATH
      wholeProcess(report, job, runs);
#endif
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_startup: %s\n", e.what());
    return 1;
  }
  std::printf("load average: %s at start, %s at end\n",
              loadAtStart.c_str(), loadAverage().c_str());
  report.note("loadAverageAtEnd", loadAverage());
  report.finish();
  return 0;
}
