// The batch engine: rows in job order, as many jobs at once as threads, a failing job (a throw,
// a failed write) reported in its row while the others finish, the same files bitwise for 1
// and 2 threads, validation of the files as written, and the CSV report's quoting.
#include "genmod/kernel/fn.hpp"
#include "genmod/tessellate/batch.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/mesh_io.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

namespace fs = std::filesystem;

class Batch : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("genmod_batch_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A sphere of radius r meshed by mesh_implicit (itself parallel), with its error bound.
BatchMesh implicit_sphere(double r, double min_feature) {
  const Fn f = square(x(0)) + square(x(1)) + square(x(2)) - r * r;
  const Box3 box{Interval(-2, 2), Interval(-2, 2), Interval(-2, 2)};
  ImplicitMesh m = mesh_implicit(f, box, {.min_feature = min_feature});
  return {std::move(m.mesh), m.stats.max_vertex_error, m.stats.limits_hit, {}};
}

// A closed, outward octahedron scaled by s.
Mesh octahedron(double s) {
  Mesh m;
  m.vertices = {{s, 0, 0}, {-s, 0, 0}, {0, s, 0}, {0, -s, 0}, {0, 0, s}, {0, 0, -s}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// Jobs of very different cost (the first is the slowest), so that with two threads they
// finish out of order.
std::vector<BatchJob> mixed_jobs(const fs::path& dir) {
  std::vector<BatchJob> jobs;
  jobs.push_back({"fine sphere", dir / "fine.ply", [] { return implicit_sphere(1.0, 0.03); }});
  for (int i = 1; i <= 4; ++i)
    jobs.push_back({"octahedron " + std::to_string(i), dir / ("oct" + std::to_string(i) + ".obj"),
                    [i] { return BatchMesh{octahedron(i), std::nullopt, {}, {}}; }});
  jobs.push_back({"coarse sphere", dir / "coarse.stl", [] { return implicit_sphere(1.5, 0.2); }});
  jobs.push_back({"sphere off", dir / "sphere.off", [] { return implicit_sphere(0.7, 0.1); }});
  return jobs;
}

TEST_F(Batch, RowsComeBackInJobOrderWithTheMeshesCounts) {
  const std::vector<BatchJob> jobs = mixed_jobs(dir_);
  std::vector<std::pair<std::size_t, std::size_t>> progress;
  const std::vector<BatchResult> rows = run_batch(
      jobs, {.threads = 2, .progress = [&](std::size_t done, std::size_t total) { progress.emplace_back(done, total); }});
  ASSERT_EQ(rows.size(), jobs.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE(rows[i].name + ": " + rows[i].message);
    EXPECT_EQ(rows[i].name, jobs[i].name);
    EXPECT_EQ(rows[i].output, jobs[i].output);
    EXPECT_EQ(rows[i].status, BatchStatus::Ok);
    const Mesh written = read_mesh(jobs[i].output);
    EXPECT_EQ(rows[i].triangles, written.triangles.size());
    EXPECT_EQ(rows[i].vertices, written.vertices.size());
    EXPECT_GT(rows[i].triangles, 0u);
    EXPECT_GE(rows[i].seconds, 0.0);
    ASSERT_TRUE(rows[i].valid.has_value());
    EXPECT_TRUE(*rows[i].valid);  // closed outward octahedra and implicit meshes
  }
  // The implicit jobs carry the mesher's certified bound (within its tolerance = min_feature).
  ASSERT_TRUE(rows[0].error_bound.has_value());
  EXPECT_GT(*rows[0].error_bound, 0.0);
  EXPECT_LE(*rows[0].error_bound, 0.03);
  EXPECT_FALSE(rows[1].error_bound.has_value());
  // Each row has its own job's counts (the jobs' meshes differ, so mixed-up rows would show).
  std::set<std::size_t> distinct;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const BatchMesh direct = jobs[i].make();
    EXPECT_EQ(rows[i].triangles, direct.mesh.triangles.size()) << rows[i].name;
    EXPECT_EQ(rows[i].error_bound, direct.error_bound) << rows[i].name;
    distinct.insert(direct.mesh.triangles.size());
  }
  EXPECT_EQ(distinct.size(), 4u);  // the four octahedra share a count; the three spheres differ
  EXPECT_EQ(rows[1].triangles, 8u);
  // Progress: (0, n) first, then one call per job, counting up to n.
  ASSERT_EQ(progress.size(), jobs.size() + 1);
  for (std::size_t k = 0; k < progress.size(); ++k) {
    EXPECT_EQ(progress[k].first, k);
    EXPECT_EQ(progress[k].second, jobs.size());
  }
}

TEST_F(Batch, AThrowingJobIsReportedAndTheOthersFinish) {
  std::vector<BatchJob> jobs = mixed_jobs(dir_);
  jobs[2].make = []() -> BatchMesh { throw std::runtime_error("model 2 cannot be built: radius -1 < 0"); };
  jobs[4].make = []() -> BatchMesh { throw 42; };  // not a std::exception
  const std::vector<BatchResult> rows = run_batch(jobs, {.threads = 2});
  ASSERT_EQ(rows.size(), jobs.size());
  EXPECT_EQ(rows[2].status, BatchStatus::Error);
  EXPECT_EQ(rows[2].message, "model 2 cannot be built: radius -1 < 0");
  EXPECT_FALSE(rows[2].valid.has_value());
  EXPECT_FALSE(fs::exists(jobs[2].output));
  EXPECT_EQ(rows[4].status, BatchStatus::Error);
  EXPECT_NE(rows[4].message.find("unknown exception"), std::string::npos);
  for (std::size_t i : {0, 1, 3, 5, 6}) {
    EXPECT_EQ(rows[i].status, BatchStatus::Ok) << rows[i].name << ": " << rows[i].message;
    EXPECT_TRUE(fs::exists(jobs[i].output));
  }
}

TEST_F(Batch, OneAndTwoThreadsWriteBitwiseTheSameFiles) {
  fs::create_directories(dir_ / "one");
  fs::create_directories(dir_ / "two");
  const std::vector<BatchJob> one = mixed_jobs(dir_ / "one"), two = mixed_jobs(dir_ / "two");
  const std::vector<BatchResult> rows1 = run_batch(one, {.threads = 1});
  const std::vector<BatchResult> rows2 = run_batch(two, {.threads = 2});
  ASSERT_EQ(rows1.size(), rows2.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    SCOPED_TRACE(one[i].name);
    EXPECT_EQ(rows1[i].status, BatchStatus::Ok);
    const std::string a = bytes_of(one[i].output), b = bytes_of(two[i].output);
    EXPECT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << one[i].output << " and " << two[i].output << " differ";
    EXPECT_EQ(rows1[i].triangles, rows2[i].triangles);
    EXPECT_EQ(rows1[i].error_bound, rows2[i].error_bound);
    EXPECT_EQ(rows1[i].valid, rows2[i].valid);
  }
}

// Two jobs that each wait for the other to have started: with two threads both finish, with
// one thread the first to run gives up (after `patience`), which shows the cap is kept.
std::vector<BatchResult> run_rendezvous(const fs::path& dir, int threads, std::chrono::milliseconds patience) {
  std::mutex lock;
  std::condition_variable changed;
  int started = 0;
  auto job = [&](const std::string& name) {
    return BatchJob{name, dir / (name + ".obj"), [&, patience] {
                      std::unique_lock<std::mutex> hold(lock);
                      ++started;
                      changed.notify_all();
                      if (!changed.wait_for(hold, patience, [&] { return started == 2; }))
                        throw std::runtime_error("the other job did not start");
                      return BatchMesh{octahedron(1.0), {}, {}, {}};
                    }};
  };
  return run_batch({job("a"), job("b")}, {.threads = threads, .validate = false});
}

TEST_F(Batch, TheThreadCountIsHowManyJobsRunAtOnce) {
  // Generous: a loaded machine may be slow to start the second worker.
  const std::vector<BatchResult> two = run_rendezvous(dir_, 2, std::chrono::seconds(60));
  EXPECT_EQ(two[0].status, BatchStatus::Ok) << two[0].message;
  EXPECT_EQ(two[1].status, BatchStatus::Ok) << two[1].message;
  fs::remove_all(dir_);
  fs::create_directories(dir_);
  const std::vector<BatchResult> one = run_rendezvous(dir_, 1, std::chrono::milliseconds(200));
  const int failed = (one[0].status == BatchStatus::Error) + (one[1].status == BatchStatus::Error);
  EXPECT_EQ(failed, 1);
  EXPECT_EQ(one[0].status == BatchStatus::Error ? one[0].message : one[1].message, "the other job did not start");
}

// Once the stop request is set, jobs not started are error rows; none is dropped.
TEST_F(Batch, CancelledJobsAreErrorRows) {
  std::atomic<bool> stop{false};
  std::vector<BatchJob> jobs = mixed_jobs(dir_);
  jobs[0].make = [&stop, make = jobs[0].make] {
    stop = true;
    return make();
  };
  const std::vector<BatchResult> rows = run_batch(jobs, {.threads = 1, .cancel = &stop});
  ASSERT_EQ(rows.size(), jobs.size());
  EXPECT_EQ(rows[0].status, BatchStatus::Ok);  // running when the request came: finished
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].status, BatchStatus::Error);
    EXPECT_EQ(rows[i].name, jobs[i].name);
    EXPECT_EQ(rows[i].message, "cancelled before it ran");
    EXPECT_FALSE(fs::exists(jobs[i].output));
  }
}

TEST_F(Batch, AFailedWriteIsTheJobsError) {
  std::vector<BatchJob> jobs = mixed_jobs(dir_);
  jobs[1].output = dir_ / "no" / "such" / "dir" / "oct.obj";
  const bool have_full = fs::exists("/dev/full");
  if (have_full) {
    fs::create_symlink("/dev/full", dir_ / "full.ply");
    jobs[3].output = dir_ / "full.ply";
  }
  const std::vector<BatchResult> rows = run_batch(jobs, {.threads = 2});
  EXPECT_EQ(rows[1].status, BatchStatus::Error);
  EXPECT_NE(rows[1].message.find("oct.obj"), std::string::npos) << rows[1].message;
  EXPECT_EQ(rows[1].triangles, 8u);  // the mesh was made; only its write failed
  EXPECT_FALSE(rows[1].valid.has_value());
  if (have_full) {
    EXPECT_EQ(rows[3].status, BatchStatus::Error);
    EXPECT_NE(rows[3].message.find("full.ply"), std::string::npos) << rows[3].message;
  }
  for (std::size_t i : {0, 2, 4, 5, 6}) EXPECT_EQ(rows[i].status, BatchStatus::Ok) << rows[i].message;
}

TEST_F(Batch, ValidationOfTheWrittenFileIsReportedNotAFailure) {
  Mesh open = octahedron(1.0);
  open.triangles.pop_back();  // a hole: three boundary edges
  std::vector<BatchJob> jobs{{"open", dir_ / "open.obj", [open] { return BatchMesh{open, std::nullopt, {}, "note"}; }},
                             {"closed", dir_ / "closed.obj", [] { return BatchMesh{octahedron(1.0), {}, {}, {}}; }}};
  std::vector<BatchResult> rows = run_batch(jobs, {.threads = 1});
  EXPECT_EQ(rows[0].status, BatchStatus::Ok);
  ASSERT_TRUE(rows[0].valid.has_value());
  EXPECT_FALSE(*rows[0].valid);
  EXPECT_EQ(rows[0].message, "note; not valid: 3 boundary edges");
  EXPECT_EQ(rows[1].valid, std::optional<bool>(true));
  EXPECT_EQ(rows[1].message, "");
  rows = run_batch(jobs, {.threads = 1, .validate = false});
  EXPECT_FALSE(rows[0].valid.has_value());
  EXPECT_EQ(rows[0].message, "note");
}

TEST_F(Batch, BadBatchesAreRefusedBeforeAnyJobRuns) {
  int ran = 0;
  auto job = [&ran](const fs::path& out) {
    return BatchJob{"j", out, [&ran] {
                      ++ran;
                      return BatchMesh{octahedron(1.0), {}, {}, {}};
                    }};
  };
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(message([&] { run_batch({job(dir_ / "a.obj"), job(dir_ / "x/../a.obj")}); }).find("earlier job"),
            std::string::npos);
  EXPECT_NE(message([&] { run_batch({job(dir_ / "a.obj")}, {.threads = -1}); }).find("threads"), std::string::npos);
  EXPECT_NE(message([&] { run_batch({BatchJob{"empty", dir_ / "e.obj", nullptr}}); }).find("no callable"),
            std::string::npos);
  EXPECT_EQ(ran, 0);
  EXPECT_TRUE(run_batch({}).empty());
}

TEST(BatchReport, CsvQuotesFieldsThatNeedIt) {
  BatchResult ok{"torus, fine", "out/t.obj", BatchStatus::Ok, 10, 7, 0.5, 0.001, {"cells", "seconds"}, true, ""};
  BatchResult bad{"say \"hi\"", "b.obj", BatchStatus::Error, 0, 0, 0.25, std::nullopt, {}, std::nullopt,
                  "line one\nline two"};
  const std::string csv = batch_report_csv({ok, bad});
  EXPECT_EQ(csv,
            "name,output,status,triangles,vertices,seconds,error_bound,limits_hit,valid,message\n"
            "\"torus, fine\",out/t.obj,ok,10,7,0.5,0.001,cells;seconds,yes,\n"
            "\"say \"\"hi\"\"\",b.obj,error,0,0,0.25,,,,\"line one\nline two\"\n");
}

}  // namespace
}  // namespace genmod
