// Jobs files (batch_jobs.hpp): reading lines into job descriptions and printing them back.
#include "genmod/models/batch_jobs.hpp"

#include "genmod/kernel/number_text.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/tessellate/mesh_io.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

namespace genmod::models {
namespace {

// Keys that are settings, not model parameters, and which kinds of model take them.
enum class KeyUse { Parametric, Implicit, Any };
struct SettingKey {
  const char* name;
  KeyUse use;
};
constexpr SettingKey kSettings[] = {{"out", KeyUse::Any},          {"res", KeyUse::Parametric},
                                    {"box", KeyUse::Implicit},     {"min_feature", KeyUse::Implicit},
                                    {"tolerance", KeyUse::Any}, {"max_cell", KeyUse::Implicit},
                                    {"max_cells", KeyUse::Implicit}, {"max_seconds", KeyUse::Any}};

const SettingKey* find_setting(const std::string& key) {
  for (const SettingKey& s : kSettings)
    if (key == s.name) return &s;
  return nullptr;
}

// A line split into tokens: quotes group, '#' outside quotes ends the line.
struct Token {
  std::string text;
  bool quoted_before_equals = false;  // a quote appeared before the first '=' (no key then)
};

std::vector<Token> tokenize(std::string_view line, const std::string& where) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i == line.size() || line[i] == '#') break;
    Token t;
    bool seen_equals = false;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#') {
      if (line[i] != '"') {
        if (line[i] == '=') seen_equals = true;
        t.text += line[i++];
        continue;
      }
      if (!seen_equals) t.quoted_before_equals = true;
      ++i;
      while (true) {
        if (i == line.size()) throw JobsFileError(where + ": unterminated quote");
        if (line[i] == '"') break;
        if (line[i] == '\\' && i + 1 < line.size() && (line[i + 1] == '"' || line[i + 1] == '\\')) ++i;
        t.text += line[i++];
      }
      ++i;  // the closing quote
    }
    tokens.push_back(std::move(t));
  }
  return tokens;
}

std::string quote_if_needed(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_of(" \t\r\n#\"\\=") == std::string::npos;
  if (plain) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

bool is_key_name(const std::string& key) {
  if (key.empty() || !(std::isalpha(static_cast<unsigned char>(key[0])) || key[0] == '_')) return false;
  for (char c : key)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

double number(const std::string& key, const std::string& text, const std::string& where) {
  const std::optional<double> v = parse_double(text);
  if (!v || !std::isfinite(*v))
    throw JobsFileError(where + ": " + key + "='" + printable(text, 80) + "' is not a finite number");
  return *v;
}

// v rounded to 15 significant digits, so that sweep values (and the output names made from
// them) are the decimals a user expects: 0.1:0.7:4 gives 0.3, not 0.30000000000000004.
double fifteen_digits(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v, std::chars_format::general, 15).ptr;
  return parse_double(std::string_view(text, static_cast<std::size_t>(end - text))).value_or(v);
}

// A value or a sweep LO:HI:COUNT, as the list of values it stands for.
std::vector<double> values_of(const std::string& key, const std::string& text, const std::string& where) {
  const std::size_t first = text.find(':');
  if (first == std::string::npos) return {number(key, text, where)};
  const std::size_t second = text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
    throw JobsFileError(where + ": " + key + "='" + printable(text, 80) + "': a sweep is LO:HI:COUNT");
  const double lo = number(key + " (sweep start)", text.substr(0, first), where);
  const double hi = number(key + " (sweep end)", text.substr(first + 1, second - first - 1), where);
  const double count = number(key + " (sweep count)", text.substr(second + 1), where);
  if (count != std::floor(count) || count < 2 || count > 1e6)
    throw JobsFileError(where + ": " + key + " sweep count must be an integer in 2..1000000, got '" +
                        text.substr(second + 1) + "'");
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> values{lo};
  values.reserve(n);
  for (std::size_t i = 1; i + 1 < n; ++i)
    values.push_back(fifteen_digits(lo + static_cast<double>(i) * (hi - lo) / static_cast<double>(n - 1)));
  values.push_back(hi);
  return values;
}

std::array<double, 6> parse_box(const std::string& text, const std::string& where) {
  std::array<double, 6> box{};
  std::size_t start = 0, count = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (count == 6) throw JobsFileError(where + ": box='" + printable(text, 80) + "' must be 6 numbers x0,y0,z0,x1,y1,z1");
    box[count++] = number("box", part, where);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (count != 6) throw JobsFileError(where + ": box='" + printable(text, 80) + "' must be 6 numbers x0,y0,z0,x1,y1,z1");
  for (int axis = 0; axis < 3; ++axis)
    if (!(box[axis] < box[axis + 3]))
      throw JobsFileError(where + ": box='" + text + "': the lower corner must be below the upper on every axis");
  return box;
}

// Checks a numeric setting's value; returns it as stored.
void check_setting(const std::string& key, double v, const std::string& where) {
  auto fail = [&](const std::string& need) {
    throw JobsFileError(where + ": " + key + "=" + format_double(v) + ": must be " + need);
  };
  if (key == "res" && (v != std::floor(v) || v < 3 || v > 4096)) fail("an integer in 3..4096");
  if (key == "min_feature" && !(v > 0)) fail("> 0");
  if ((key == "tolerance" || key == "max_cell" || key == "max_seconds") && !(v >= 0)) fail(">= 0");
  if (key == "max_cells" && (v != std::floor(v) || v < 1 || v > 1e18)) fail("an integer >= 1");
}

void set_value(JobDescription& job, const std::string& key, double v) {
  if (key == "res") job.res = static_cast<int>(v);
  else if (key == "min_feature") job.min_feature = v;
  else if (key == "tolerance") job.tolerance = v;
  else if (key == "max_cell") job.max_cell = v;
  else if (key == "max_seconds") job.max_seconds = v;
  else if (key == "max_cells") job.max_cells = static_cast<std::size_t>(v);
  else job.parameters[key] = v;
}

std::string parameter_list(const std::vector<ModelParameter>& parameters) {
  std::string out;
  for (const ModelParameter& p : parameters) {
    if (!out.empty()) out += ", ";
    out += p.name;
  }
  return out.empty() ? "none" : out;
}

// The output name with {KEY} replaced; `keys` are the numeric keys of this job.
std::string substitute(const std::string& pattern, const std::map<std::string, double>& keys,
                       const std::string& where) {
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] == '}') throw JobsFileError(where + ": out='" + pattern + "': '}' without '{'");
    if (pattern[i] != '{') {
      out += pattern[i];
      continue;
    }
    const std::size_t close = pattern.find('}', i);
    if (close == std::string::npos) throw JobsFileError(where + ": out='" + pattern + "': '{' without '}'");
    const std::string key = pattern.substr(i + 1, close - i - 1);
    const auto it = keys.find(key);
    if (it == keys.end())
      throw JobsFileError(where + ": out='" + pattern + "': placeholder {" + key +
                          "} is not a numeric key of this line");
    out += format_double(it->second);
    i = close;
  }
  return out;
}

// The kind of the line's model; its parameters (nullptr for a .vm file, which has none).
const std::vector<ModelParameter>* classify_model(JobDescription& base, const std::string& where) {
  if (base.model.size() > 3 && base.model.compare(base.model.size() - 3, 3, ".vm") == 0) {
    base.kind = JobModelKind::ModelFile;
    return nullptr;
  }
  for (const Model& m : gallery())
    if (m.name == base.model) {
      base.kind = JobModelKind::Parametric;
      return &m.parameters;
    }
  if (const ImplicitModel* implicit = find_implicit_model(base.model)) {
    base.kind = JobModelKind::Implicit;
    return &implicit->parameters;
  }
  throw JobsFileError(where + ": unknown model '" + printable(base.model, 80) +
                      "' (not in the gallery or the implicit gallery, see `genmod list`, and not a .vm file)");
}

using NumericKeys = std::vector<std::pair<std::string, std::vector<double>>>;  // in line order

// Every combination of the numeric keys' values as a job, the last key varying fastest.
// `room`: how many more jobs the file may have (of `max_jobs`).
std::vector<JobDescription> expand(const JobDescription& base, const NumericKeys& numeric, const std::string& out,
                                   const std::string& where, std::size_t room, std::size_t max_jobs) {
  std::size_t combinations = 1;
  for (const auto& [key, values] : numeric) {
    if (values.size() > 1 && out.find("{" + key + "}") == std::string::npos)
      throw JobsFileError(where + ": " + key + " is swept, so out= must contain {" + key +
                          "} (each job needs its own file)");
    combinations *= values.size();
    if (combinations > room)
      throw JobsFileError(where + ": too many jobs (more than the limit max_jobs = " + std::to_string(max_jobs) + ")");
  }
  std::vector<JobDescription> jobs;
  for (std::size_t c = 0; c < combinations; ++c) {
    JobDescription job = base;
    std::map<std::string, double> keys;
    std::size_t rest = c;
    for (std::size_t k = numeric.size(); k-- > 0;) {
      const auto& [key, values] = numeric[k];
      const double v = values[rest % values.size()];
      rest /= values.size();
      keys[key] = v;
      set_value(job, key, v);
    }
    job.output = substitute(out, keys, where);
    if (!mesh_format(job.output))
      throw JobsFileError(where + ": out='" + printable(job.output, 120) +
                          "': unknown mesh extension (use .obj, .ply, .stl or .off)");
    jobs.push_back(std::move(job));
  }
  return jobs;
}

// The parse of one line: the jobs it expands to (none for a blank or comment line).
std::vector<JobDescription> parse_line(std::string_view line, const std::string& where, std::size_t room,
                                       std::size_t max_jobs) {
  const std::vector<Token> tokens = tokenize(line, where);
  if (tokens.empty()) return {};
  JobDescription base;
  base.model = tokens[0].text;
  if (!tokens[0].quoted_before_equals && base.model.find('=') != std::string::npos)
    throw JobsFileError(where + ": the line starts with '" + printable(base.model, 80) +
                        "'; a job line starts with the model (a gallery name or a .vm file)");
  const std::vector<ModelParameter>* parameters = classify_model(base, where);
  std::map<std::string, bool> seen;
  std::optional<std::string> out;
  NumericKeys numeric;
  for (std::size_t t = 1; t < tokens.size(); ++t) {
    const std::string& text = tokens[t].text;
    const std::size_t eq = tokens[t].quoted_before_equals ? std::string::npos : text.find('=');
    if (eq == std::string::npos)
      throw JobsFileError(where + ": '" + printable(text, 80) + "' is not KEY=VALUE");
    const std::string key = text.substr(0, eq), value = text.substr(eq + 1);
    if (!is_key_name(key)) throw JobsFileError(where + ": '" + printable(key, 80) + "' is not a key name");
    if (seen[key]) throw JobsFileError(where + ": " + key + "= is given twice");
    seen[key] = true;
    const SettingKey* setting = find_setting(key);
    if (setting) {
      if (setting->use == KeyUse::Parametric && base.kind != JobModelKind::Parametric)
        throw JobsFileError(where + ": " + key + "= applies to gallery (parametric) models, not to implicit model '" +
                            base.model + "' (use min_feature=)");
      if (setting->use == KeyUse::Implicit && base.kind == JobModelKind::Parametric)
        throw JobsFileError(where + ": " + key + "= applies to implicit models, not to gallery model '" +
                            base.model + "' (use res=)");
      if (key == "out") {
        out = value;
        continue;
      }
      if (key == "box") {
        base.box = parse_box(value, where);
        continue;
      }
    } else if (!parameters) {
      throw JobsFileError(where + ": unknown key '" + key + "' (a .vm model has no parameters; keys: out, box, "
                          "min_feature, tolerance, max_cell, max_cells, max_seconds)");
    } else {
      bool known = false;
      for (const ModelParameter& p : *parameters) known = known || p.name == key;
      if (!known)
        throw JobsFileError(where + ": unknown parameter '" + key + "' of model " + base.model +
                            " (parameters: " + parameter_list(*parameters) + ")");
    }
    std::vector<double> values = values_of(key, value, where);
    for (double v : values) check_setting(key, v, where);
    numeric.emplace_back(key, std::move(values));
  }
  if (!out) throw JobsFileError(where + ": missing out=FILE (the mesh file to write)");
  if (out->empty()) throw JobsFileError(where + ": out= is empty");
  if (base.kind == JobModelKind::ModelFile && !seen["min_feature"])
    throw JobsFileError(where + ": missing min_feature=H (the smallest cell edge) for the .vm model");
  return expand(base, numeric, *out, where, room, max_jobs);
}

}  // namespace

std::vector<JobDescription> parse_jobs(std::string_view text, const std::string& source_name,
                                       const JobsFileLimits& limits) {
  std::vector<JobDescription> jobs;
  std::map<std::filesystem::path, std::size_t> output_lines;  // normalized output -> line
  std::size_t line_number = 0, start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    ++line_number;
    const std::string where = source_name + " line " + std::to_string(line_number);
    const std::vector<JobDescription> line_jobs =
        parse_line(text.substr(start, end - start), where, limits.max_jobs - jobs.size(), limits.max_jobs);
    for (const JobDescription& job : line_jobs) {
      const std::filesystem::path key = std::filesystem::path(job.output).lexically_normal();
      const auto [it, fresh] = output_lines.emplace(key, line_number);
      if (!fresh)
        throw JobsFileError(where + ": output '" + job.output + "' is also written by " +
                            (it->second == line_number ? std::string("another job of this line")
                                                       : "line " + std::to_string(it->second)));
    }
    jobs.insert(jobs.end(), line_jobs.begin(), line_jobs.end());
    start = end + 1;
  }
  return jobs;
}

std::vector<JobDescription> read_jobs_file(const std::filesystem::path& path, const JobsFileLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw JobsFileError("genmod: cannot read jobs file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw JobsFileError("genmod: error reading jobs file '" + path.string() + "'");
  return parse_jobs(text.str(), path.string(), limits);
}

JobDescription parse_job(std::string_view line) {
  if (line.find('\n') != std::string_view::npos) throw JobsFileError("job line: contains a line break");
  std::vector<JobDescription> jobs = parse_line(line, "job line", JobsFileLimits{}.max_jobs, JobsFileLimits{}.max_jobs);
  if (jobs.empty()) throw JobsFileError("job line: no job (blank or a comment)");
  if (jobs.size() > 1)
    throw JobsFileError("job line: its sweeps give " + std::to_string(jobs.size()) + " jobs; a job line describes one");
  return std::move(jobs[0]);
}

std::string to_line(const JobDescription& job) {
  std::string line = quote_if_needed(job.model);
  auto add = [&line](const std::string& key, const std::string& value) { line += " " + key + "=" + value; };
  for (const auto& [name, value] : job.parameters) add(name, format_double(value));
  if (job.res) add("res", std::to_string(*job.res));
  if (job.box) {
    std::string box;
    for (double v : *job.box) {
      if (!box.empty()) box += ',';
      box += format_double(v);
    }
    add("box", box);
  }
  if (job.min_feature) add("min_feature", format_double(*job.min_feature));
  if (job.tolerance) add("tolerance", format_double(*job.tolerance));
  if (job.max_cell) add("max_cell", format_double(*job.max_cell));
  if (job.max_cells) add("max_cells", std::to_string(*job.max_cells));
  if (job.max_seconds) add("max_seconds", format_double(*job.max_seconds));
  // Braces would read as placeholders: a literal brace cannot come back, so say so.
  if (job.output.find_first_of("{}") != std::string::npos)
    throw std::invalid_argument("genmod: to_line: output '" + job.output + "' contains a brace");
  add("out", quote_if_needed(job.output));
  return line;
}

std::string job_name(const JobDescription& job) {
  JobDescription unnamed = job;
  unnamed.output = "x.obj";
  std::string line = to_line(unnamed);
  return line.substr(0, line.size() - std::string(" out=x.obj").size());
}

}  // namespace genmod::models
