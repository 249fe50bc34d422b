// Jobs files: the syntax (models, settings, sweeps, placeholders, quotes, comments), every
// error named with its file, line and problem, to_line / parse_job round trips, and a mixed
// list with one deliberately bad job meshed end to end by the batch engine.
#include "genmod/models/batch_jobs.hpp"
#include "genmod/tessellate/mesh_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

namespace fs = std::filesystem;

// The message of the JobsFileError that parsing `text` throws, or "no error".
std::string parse_error(const std::string& text) {
  try {
    parse_jobs(text, "jobs.txt");
  } catch (const JobsFileError& e) {
    return e.what();
  }
  return "no error";
}

#define EXPECT_HAS(text, needle) EXPECT_NE(std::string(text).find(needle), std::string::npos) << (text)

TEST(JobsFile, ParsesTheThreeKindsOfModelWithCommentsAndBlankLines) {
  const std::vector<JobDescription> jobs = parse_jobs(
      "# a comment line\n"
      "\n"
      "doorknob res=48 bulge_radius=0.9 out=knob.obj   # trailing comment\n"
      "   \t\n"
      "tanglecube min_feature=0.2 tolerance=0.05 out=sub/tangle.off\r\n"
      "data/tanglecube.vm box=-2,-2,-2,2,2,2.5 min_feature=0.05 max_cells=1000 max_seconds=10 out=tangle.stl\n",
      "jobs.txt");
  ASSERT_EQ(jobs.size(), 3u);
  EXPECT_EQ(jobs[0].model, "doorknob");
  EXPECT_EQ(jobs[0].kind, JobModelKind::Parametric);
  EXPECT_EQ(jobs[0].res, 48);
  EXPECT_EQ(jobs[0].parameters, (ParameterValues{{"bulge_radius", 0.9}}));
  EXPECT_EQ(jobs[0].output, "knob.obj");
  EXPECT_EQ(jobs[1].kind, JobModelKind::Implicit);
  EXPECT_EQ(jobs[1].min_feature, 0.2);
  EXPECT_EQ(jobs[1].tolerance, 0.05);
  EXPECT_FALSE(jobs[1].res.has_value());
  EXPECT_EQ(jobs[1].output, "sub/tangle.off");
  EXPECT_EQ(jobs[2].kind, JobModelKind::ModelFile);
  EXPECT_EQ(jobs[2].model, "data/tanglecube.vm");
  EXPECT_EQ(jobs[2].box, (std::array<double, 6>{-2, -2, -2, 2, 2, 2.5}));
  EXPECT_EQ(jobs[2].max_cells, 1000u);
  EXPECT_EQ(jobs[2].max_seconds, 10.0);
}

TEST(JobsFile, SweepsExpandToEveryCombinationWithPlaceholdersSubstituted) {
  const std::vector<JobDescription> jobs =
      parse_jobs("torus res=32 major_radius=1:2:5 out=torus_{major_radius}.ply\n"
                 "torus minor_radius=0.1:0.3:3 res=8:16:2 out=t/{res}_{minor_radius}.obj\n",
                 "jobs.txt");
  ASSERT_EQ(jobs.size(), 5u + 6u);
  const double radii[] = {1, 1.25, 1.5, 1.75, 2};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(jobs[i].parameters.at("major_radius"), radii[i]);
    EXPECT_EQ(jobs[i].res, 32);
  }
  EXPECT_EQ(jobs[0].output, "torus_1.ply");
  EXPECT_EQ(jobs[1].output, "torus_1.25.ply");
  EXPECT_EQ(jobs[4].output, "torus_2.ply");
  // The first swept key varies slowest; the last value is HI exactly.
  const char* expected[] = {"t/8_0.1.obj", "t/16_0.1.obj", "t/8_0.2.obj", "t/16_0.2.obj", "t/8_0.3.obj", "t/16_0.3.obj"};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(jobs[5 + i].output, expected[i]);
  EXPECT_EQ(jobs[10].parameters.at("minor_radius"), 0.3);
  EXPECT_EQ(jobs[10].res, 16);
  // Values between the ends are rounded to 15 digits: the names are the expected decimals.
  const std::vector<JobDescription> tenths = parse_jobs("sphere radius=0.1:0.7:4 out=s{radius}.obj", "j");
  ASSERT_EQ(tenths.size(), 4u);
  EXPECT_EQ(tenths[1].output, "s0.3.obj");
  EXPECT_EQ(tenths[1].parameters.at("radius"), 0.3);
  EXPECT_EQ(tenths[2].output, "s0.5.obj");
  // The ends are the numbers as written, all 17 digits kept.
  const std::vector<JobDescription> exact =
      parse_jobs("sphere radius=0.10000000000000002:0.30000000000000004:3 out=s{radius}.obj", "j");
  EXPECT_EQ(exact[0].parameters.at("radius"), 0.10000000000000002);
  EXPECT_EQ(exact[2].parameters.at("radius"), 0.30000000000000004);
  EXPECT_EQ(exact[1].output, "s0.2.obj");
}

TEST(JobsFile, ErrorsNameTheFileTheLineAndTheProblem) {
  struct Case {
    const char* text;
    std::vector<const char*> needles;
  };
  const Case cases[] = {
      {"torus out=a.obj\nteapot out=b.obj\n", {"jobs.txt line 2", "unknown model 'teapot'"}},
      {"torus radius=2 out=a.obj", {"jobs.txt line 1", "unknown parameter 'radius'", "major_radius"}},
      {"torus res=8 res=9 out=a.obj", {"line 1", "res= is given twice"}},
      {"torus out=a.obj out=b.obj", {"out= is given twice"}},
      {"#\n\ntorus major_radius=abc out=a.obj", {"jobs.txt line 3", "major_radius='abc'", "not a finite number"}},
      {"torus major_radius=nan out=a.obj", {"not a finite number"}},
      {"torus major_radius=1:2 out=a_{major_radius}.obj", {"LO:HI:COUNT"}},
      {"torus major_radius=1:2:1 out=a_{major_radius}.obj", {"sweep count"}},
      {"torus major_radius=1:2:2.5 out=a_{major_radius}.obj", {"sweep count"}},
      {"torus res=32", {"line 1", "missing out="}},
      {"torus out=", {"out= is empty"}},
      {"torus major_radius=1:2:3 out=a.obj", {"major_radius is swept", "{major_radius}"}},
      {"torus out=a.obj\nsphere out=b.obj\ntorus res=8 out=./a.obj\n", {"jobs.txt line 3", "output './a.obj'", "line 1"}},
      {"torus minor_radius=0.1:0.1:2 out=t{minor_radius}.obj", {"another job of this line"}},
      {"torus out=a.xyz", {"unknown mesh extension"}},
      {"torus out=a_{res}.obj", {"placeholder {res}"}},
      {"torus out=a_{res.obj", {"'{' without '}'"}},
      {"torus res=2 out=a.obj", {"res=2", "3..4096"}},
      {"torus res=10.5 out=a.obj", {"res=10.5"}},
      {"torus min_feature=0.1 out=a.obj", {"min_feature= applies to implicit models", "res="}},
      {"tanglecube res=10 out=a.obj", {"res= applies to gallery"}},
      {"x.vm out=a.obj", {"missing min_feature"}},
      {"x.vm min_feature=0.1 radius=1 out=a.obj", {"unknown key 'radius'", ".vm model has no parameters"}},
      {"x.vm min_feature=0 out=a.obj", {"min_feature=0", "> 0"}},
      {"x.vm min_feature=0.1 box=1,2,3 out=a.obj", {"6 numbers"}},
      {"x.vm min_feature=0.1 box=0,0,0,1,-1,1 out=a.obj", {"lower corner"}},
      {"tanglecube tolerance=-1 out=a.obj", {"tolerance=-1", ">= 0"}},
      {"tanglecube max_cells=0 out=a.obj", {"max_cells=0"}},
      {"torus bogus out=a.obj", {"'bogus' is not KEY=VALUE"}},
      {"out=a.obj torus", {"starts with 'out=a.obj'"}},
      {"torus out=\"a.obj", {"unterminated quote"}},
      {"torus 1x=2 out=a.obj", {"'1x' is not a key name"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message = parse_error(c.text);
    for (const char* needle : c.needles) EXPECT_HAS(message, needle);
  }
}

TEST(JobsFile, TooManyJobsIsTheNamedLimit) {
  try {
    parse_jobs("torus major_radius=1:2:10 minor_radius=0.1:0.2:10 out=t{major_radius}_{minor_radius}.obj", "j",
               {.max_jobs = 99});
    FAIL() << "no error";
  } catch (const JobsFileError& e) {
    EXPECT_HAS(e.what(), "max_jobs = 99");
  }
  EXPECT_EQ(parse_jobs("torus major_radius=1:2:10 minor_radius=0.1:0.2:10 out=t{major_radius}_{minor_radius}.obj",
                       "j", {.max_jobs = 100})
                .size(),
            100u);
}

TEST(JobsFile, QuotedValuesHoldSpacesHashesAndQuotes) {
  const std::vector<JobDescription> jobs =
      parse_jobs("\"my models/odd #1.vm\" min_feature=0.1 out=\"out dir/say \\\"hi\\\" #2.obj\" # comment", "j");
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].model, "my models/odd #1.vm");
  EXPECT_EQ(jobs[0].output, "out dir/say \"hi\" #2.obj");
  EXPECT_EQ(parse_job(to_line(jobs[0])), jobs[0]);
}

TEST(JobsFile, ToLineParsesBackToTheSameJob) {
  // Every job of a file with sweeps, and random parameter values that need all 17 digits.
  std::vector<JobDescription> jobs =
      parse_jobs("torus res=7:19:3 major_radius=0.1:3:7 out=a_{res}_{major_radius}.ply\n"
                 "tanglecube box=-2.5,-2,-2,2,2,1e-3 min_feature=0.1 tolerance=0 max_cell=0.5 max_cells=77 "
                 "max_seconds=1.5 out=/abs/t.stl\n"
                 "data/tanglecube.vm min_feature=0.05 out=tangle.off\n"
                 "blobby out=b.obj\n",
                 "j");
  std::mt19937_64 random(14);
  std::uniform_real_distribution<double> value(-10, 10);
  for (const Model& m : gallery()) {
    JobDescription j;
    j.model = m.name;
    for (const ModelParameter& p : m.parameters) j.parameters[p.name] = value(random);
    j.res = 3 + static_cast<int>(random() % 4000);
    j.output = m.name + ".obj";
    jobs.push_back(j);
  }
  for (const JobDescription& j : jobs) {
    const std::string line = to_line(j);
    SCOPED_TRACE(line);
    EXPECT_EQ(parse_job(line), j);
    EXPECT_EQ(parse_jobs(line + "\n", "j"), std::vector<JobDescription>{j});
  }
  EXPECT_EQ(to_line(jobs[0]), "torus major_radius=0.1 res=7 out=a_7_0.1.ply");
  EXPECT_EQ(job_name(jobs[0]), "torus major_radius=0.1 res=7");
  EXPECT_THROW(parse_job("torus major_radius=1:2:3 out=a{major_radius}.obj"), JobsFileError);
  EXPECT_THROW(parse_job("# only a comment"), JobsFileError);
}

class JobsRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / "genmod_batch_jobs_test";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(JobsRun, AMixedListWithOneBadJobIsMeshedEndToEnd) {
  const std::string data = GENMOD_DATA_DIR;
  const fs::path jobs_file = dir_ / "jobs.txt";
  std::ofstream(jobs_file) << "# gallery, sweep, implicit gallery, .vm file, and a bad parameter value\n"
                           << "doorknob res=24 bulge_radius=0.9 out=knob.obj\n"
                           << "torus res=16 major_radius=1:2:3 out=torus_{major_radius}.ply\n"
                           << "tanglecube min_feature=0.25 out=tangle_gallery.off\n"
                           << "\"" << data << "/tanglecube.vm\" box=-2.5,-2.5,-2.5,2.5,2.5,2.5 min_feature=0.25 "
                           << "out=tangle_file.stl\n"
                           << "torus res=16 minor_radius=-1 out=bad_torus.obj\n"
                           << "/no/such/model.vm min_feature=0.1 out=missing.obj\n";
  const std::vector<JobDescription> jobs = read_jobs_file(jobs_file);
  ASSERT_EQ(jobs.size(), 8u);
  fs::create_directories(dir_ / "out");
  const std::vector<BatchResult> rows = run_batch(make_batch_jobs(jobs, dir_ / "out"), {.threads = 2});
  ASSERT_EQ(rows.size(), 8u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BatchResult& r = rows[i];
    SCOPED_TRACE(r.name + ": " + r.message);
    EXPECT_EQ(r.name, job_name(jobs[i]));
    EXPECT_EQ(r.output, dir_ / "out" / jobs[i].output);
    if (i == 6) {  // minor_radius=-1: the model refuses it when built
      EXPECT_EQ(r.status, BatchStatus::Error);
      EXPECT_HAS(r.message, "minor_radius");
      EXPECT_FALSE(fs::exists(r.output));
      continue;
    }
    if (i == 7) {  // the missing .vm file
      EXPECT_EQ(r.status, BatchStatus::Error);
      EXPECT_HAS(r.message, "/no/such/model.vm");
      continue;
    }
    EXPECT_EQ(r.status, BatchStatus::Ok);
    const Mesh m = read_mesh(r.output);
    EXPECT_EQ(m.triangles.size(), r.triangles);
    EXPECT_GT(r.triangles, 0u);
    ASSERT_TRUE(r.valid.has_value());
    if (i >= 4) {  // the implicit jobs: valid meshes with a certified bound below the tolerance
      EXPECT_TRUE(*r.valid);
      ASSERT_TRUE(r.error_bound.has_value());
      EXPECT_LE(*r.error_bound, 0.25);
    } else {
      EXPECT_FALSE(r.error_bound.has_value());  // the lattice mesher gives none (yet)
    }
  }
  // The sweep's meshes differ: the torus grew.
  EXPECT_NE(read_mesh(rows[1].output).vertices, read_mesh(rows[3].output).vertices);
}

TEST(JobsFile, AMissingFileIsNamed) {
  try {
    read_jobs_file("/no/such/jobs.txt");
    FAIL() << "no error";
  } catch (const JobsFileError& e) {
    EXPECT_HAS(e.what(), "/no/such/jobs.txt");
  }
}

}  // namespace
}  // namespace genmod::models
