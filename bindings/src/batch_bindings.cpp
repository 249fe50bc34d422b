// The batch engine from Python (genmod.batch wraps these): jobs travel as their one-line text
// (models/batch_jobs.hpp), so a worker process on another machine meshes exactly the job the
// client described, with the same C++ engine as `genmod batch`.
#include "bindings.hpp"
#include "interruptible.hpp"

#include "genmod/models/batch_jobs.hpp"
#include "genmod/tessellate/batch.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

namespace py = pybind11;

namespace genmod::python {
namespace {

py::dict row(const BatchResult& r) {
  py::dict d;
  d["name"] = r.name;
  d["output"] = r.output.string();
  d["status"] = std::string(to_string(r.status));
  d["triangles"] = r.triangles;
  d["vertices"] = r.vertices;
  d["seconds"] = r.seconds;
  d["error_bound"] = r.error_bound ? py::object(py::float_(*r.error_bound)) : py::object(py::none());
  d["limits_hit"] = r.limits_hit;
  d["valid"] = r.valid ? py::object(py::bool_(*r.valid)) : py::object(py::none());
  d["message"] = r.message;
  return d;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def("_parse_jobs", [](const std::string& text, const std::string& source) {
    std::vector<std::string> lines;
    for (const models::JobDescription& job : models::parse_jobs(text, source)) lines.push_back(models::to_line(job));
    return lines;
  }, py::arg("text"), py::arg("source") = "<jobs>");
  m.def("_run_jobs", [](const std::vector<std::string>& lines, const std::filesystem::path& output_dir, int threads,
                        bool validate) {
    std::vector<models::JobDescription> jobs;
    for (const std::string& line : lines) jobs.push_back(models::parse_job(line));
    BatchOptions options;
    options.threads = threads;
    options.validate = validate;
    std::atomic<bool> cancel{false};
    options.cancel = &cancel;
    const std::vector<BatchResult> rows =
        run_interruptible(cancel, [&] { return run_batch(models::make_batch_jobs(jobs, output_dir), options); });
    py::list out;
    for (const BatchResult& r : rows) out.append(row(r));
    return out;
  }, py::arg("lines"), py::arg("output_dir"), py::arg("threads") = 0, py::arg("validate") = true);
}

}  // namespace genmod::python
