#include "genmod/procedural/procedure.hpp"

#include "genmod/procedural/mesh_hash.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace genmod {
namespace {

// Built by appends: GCC 12 gives a false -Wrestrict on "'" + std::string(s) + "'".
std::string quoted(std::string_view s) {
  std::string q;
  q.reserve(s.size() + 2);
  q.push_back('\'');
  q.append(s);
  q.push_back('\'');
  return q;
}

[[noreturn]] void refuse(std::string_view what, std::string_view procedure, const std::string& problem) {
  throw std::invalid_argument(std::string(what) + " " + quoted(procedure) + ": " + problem);
}

void append_u64(std::string& out, std::uint64_t v) {
  char bytes[8];
  std::memcpy(bytes, &v, 8);
  out.append(bytes, 8);
}

}  // namespace

ParamDecl param(std::string name, ParamValue default_value) {
  ParamType type = default_value.type();
  return ParamDecl{std::move(name), type, std::move(default_value)};
}

const ParamValue& Arguments::operator[](std::string_view name) const {
  for (std::size_t i = 0; i < spec_->params.size(); ++i)
    if (spec_->params[i].name == name) return values_[i];
  refuse("procedure", spec_->name, "the body reads an undeclared parameter " + quoted(name));
}

std::string signature_string(const ProcedureSpec& spec) {
  std::string s = spec.mode == Mode::InOut ? "INOUT" : spec.mode == Mode::Out ? "OUT" : "UNSET";
  s += ':';
  for (std::size_t i = 0; i < spec.params.size(); ++i) {
    if (i) s += ':';
    s += java_type_name(spec.params[i].type);
    s += ',';
    s += spec.params[i].name;
  }
  return s;
}

void ProcedureRegistry::add(ProcedureSpec spec) {
  if (spec.name.empty()) throw std::invalid_argument("register procedure: the name is empty");
  if (procedures_.count(spec.name)) refuse("register procedure", spec.name, "a procedure of that name exists");
  if (spec.mode == Mode::Unset) refuse("register procedure", spec.name, "no mode (Out or InOut)");
  if (spec.mode == Mode::Out && !spec.out_body) refuse("register procedure", spec.name, "an Out procedure needs out_body");
  if (spec.mode == Mode::InOut && !spec.inout_body)
    refuse("register procedure", spec.name, "an InOut procedure needs inout_body");
  for (std::size_t i = 0; i < spec.params.size(); ++i) {
    const ParamDecl& p = spec.params[i];
    if (p.name.empty()) refuse("register procedure", spec.name, "parameter " + std::to_string(i) + " has no name");
    if (!p.default_value) refuse("register procedure", spec.name, "parameter " + quoted(p.name) + " has no default");
    if (p.default_value->type() != p.type)
      refuse("register procedure", spec.name,
             "parameter " + quoted(p.name) + " is declared " + std::string(java_type_name(p.type)) +
                 " but its default is " + std::string(java_type_name(p.default_value->type())));
    for (std::size_t j = 0; j < i; ++j)
      if (spec.params[j].name == p.name) refuse("register procedure", spec.name, "parameter " + quoted(p.name) + " is declared twice");
  }
  std::string name = spec.name;
  procedures_.emplace(std::move(name), Entry{std::move(spec), std::make_unique<ProcedureCache>(default_cache_limit_)});
}

bool ProcedureRegistry::contains(std::string_view name) const { return procedures_.find(name) != procedures_.end(); }

const ProcedureRegistry::Entry& ProcedureRegistry::entry(std::string_view name) const {
  auto it = procedures_.find(name);
  if (it == procedures_.end()) throw std::invalid_argument("call " + quoted(name) + ": no procedure of that name");
  return it->second;
}

const ProcedureSpec& ProcedureRegistry::spec(std::string_view name) const { return entry(name).spec; }

Arguments ProcedureRegistry::resolve(std::string_view name, const NamedArgs& args) const {
  const ProcedureSpec& s = spec(name);
  std::vector<ParamValue> values;
  values.reserve(s.params.size());
  for (const ParamDecl& p : s.params) values.push_back(*p.default_value);
  std::vector<bool> given(s.params.size(), false);
  for (const auto& [arg_name, value] : args) {
    std::size_t i = 0;
    while (i < s.params.size() && s.params[i].name != arg_name) ++i;
    if (i == s.params.size()) refuse("call", s.name, "unknown parameter " + quoted(arg_name) + " (signature " + signature_string(s) + ")");
    if (given[i]) refuse("call", s.name, "parameter " + quoted(arg_name) + " is given twice");
    given[i] = true;
    const ParamType want = s.params[i].type;
    if (value.type() == want) {
      values[i] = value;
    } else if (want == ParamType::Double && value.type() == ParamType::Integer &&
               std::abs(value.as_integer()) <= (std::int64_t{1} << 53)) {
      values[i] = ParamValue(static_cast<double>(value.as_integer()));
    } else {
      refuse("call", s.name,
             "parameter " + quoted(arg_name) + " is " + std::string(java_type_name(want)) + ", given " +
                 std::string(java_type_name(value.type())));
    }
  }
  return Arguments(&s, std::move(values));
}

std::optional<std::array<Vec3, 2>> ProcedureRegistry::bounds(std::string_view name, const NamedArgs& args) const {
  const ProcedureSpec& s = spec(name);
  if (!s.bounds) return std::nullopt;
  return (*s.bounds)(resolve(name, args));
}

std::string ProcedureRegistry::cache_key(const Entry& e, const Arguments& args, const Context& context,
                                         const PolyMesh* input) const {
  std::string key;
  append_u64(key, static_cast<std::uint64_t>(context.seed));
  if (e.spec.uses_lod) append_u64(key, static_cast<std::uint64_t>(static_cast<std::int64_t>(context.lod)));
  if (e.spec.uses_transform)
    for (const auto& row : context.transform.m)
      for (double x : row) append_u64(key, std::bit_cast<std::uint64_t>(x));
  if (input) {
    MeshHash h = content_hash(*input);
    append_u64(key, h.a);
    append_u64(key, h.b);
  }
  for (const ParamValue& v : args.values()) v.append_key_bytes(key);
  return key;
}

PolyMesh ProcedureRegistry::call(std::string_view name, const NamedArgs& args, const Context& context) const {
  const Entry& e = entry(name);
  if (e.spec.mode != Mode::Out) refuse("call", e.spec.name, "an InOut procedure needs a model (call_inout)");
  if (!e.spec.cacheable || !caching()) {
    Arguments resolved = resolve(name, args);
    const std::optional<Context> seen = in_view(e, resolved, context);
    if (!seen) return PolyMesh();
    return e.spec.out_body(resolved, CallContext(*this, *seen));
  }
  return *call_shared(name, args, context);  // a deep copy (OpenMesh copies properties)
}

std::shared_ptr<const PolyMesh> ProcedureRegistry::call_shared(std::string_view name, const NamedArgs& args,
                                                               const Context& context) const {
  const Entry& e = entry(name);
  if (e.spec.mode != Mode::Out) refuse("call", e.spec.name, "an InOut procedure needs a model (call_inout)");
  Arguments resolved = resolve(name, args);
  const std::optional<Context> seen = in_view(e, resolved, context);
  if (!seen) return std::make_shared<const PolyMesh>();
  CallContext inner(*this, *seen);
  // `new PolyMesh(body())` and not make_shared: PolyMesh has no move constructor, and only a
  // prvalue initialising the object directly is not a whole-mesh copy (guaranteed elision).
  if (!e.spec.cacheable || !caching()) return std::shared_ptr<const PolyMesh>(new PolyMesh(e.spec.out_body(resolved, inner)));
  std::string key = cache_key(e, resolved, *seen, nullptr);
  if (auto hit = e.cache->find(key)) return hit;
  std::shared_ptr<const PolyMesh> built(new PolyMesh(e.spec.out_body(resolved, inner)));
  e.cache->insert(key, built);
  return built;
}

void ProcedureRegistry::call_inout(std::string_view name, PolyMesh& model, const NamedArgs& args,
                                   const Context& context) const {
  const Entry& e = entry(name);
  if (e.spec.mode != Mode::InOut) refuse("call", e.spec.name, "an Out procedure takes no model (call)");
  Arguments resolved = resolve(name, args);
  const std::optional<Context> seen = in_view(e, resolved, context);
  if (!seen) return;  // culled: the model stays as it was
  CallContext inner(*this, *seen);
  if (!e.spec.cacheable || !caching()) {
    e.spec.inout_body(model, resolved, inner);
    return;
  }
  std::string key = cache_key(e, resolved, *seen, &model);
  if (auto hit = e.cache->find(key)) {
    model = *hit;
    return;
  }
  e.spec.inout_body(model, resolved, inner);
  e.cache->insert(key, std::make_shared<const PolyMesh>(model));
}

std::optional<Context> ProcedureRegistry::in_view(const Entry& e, const Arguments& args, Context context) const {
  if (!context.camera) return context;
  try {
    check_camera(*context.camera);
  } catch (const std::invalid_argument& error) {
    refuse("call", e.spec.name, error.what());
  }
  if (!e.spec.bounds) return context;
  const std::array<Vec3, 2> box = (*e.spec.bounds)(args);
  for (int axis = 0; axis < 3; ++axis)
    if (!(std::isfinite(box[0][axis]) && std::isfinite(box[1][axis]) && box[0][axis] <= box[1][axis]))
      refuse("call", e.spec.name, "the bounds are not a finite box (lo <= hi)");
  // A non-finite placement would put the box nowhere, and the frustum test would cull it.
  for (const auto& row : context.transform.m)
    for (double x : row)
      if (!std::isfinite(x)) refuse("call", e.spec.name, "the context transform is not finite");
  const BoxView view = view_of_box(*context.camera, box, context.transform);
  if (!view.visible) {
    e.culled->fetch_add(1);
    return std::nullopt;
  }
  context.lod = view.lod;
  return context;
}

std::uint64_t ProcedureRegistry::culled_calls(std::string_view name) const { return entry(name).culled->load(); }

CacheStats ProcedureRegistry::cache_stats(std::string_view name) const { return entry(name).cache->stats(); }
void ProcedureRegistry::reset_cache_stats(std::string_view name) const { entry(name).cache->reset_stats(); }
void ProcedureRegistry::set_cache_limit(std::string_view name, std::size_t limit) const {
  entry(name).cache->set_limit(limit);
}
void ProcedureRegistry::clear_caches() const {
  for (const auto& [name, e] : procedures_) e.cache->clear();
}

namespace {
Context overridden(Context c, const CallOptions& o) {
  if (o.seed) c.seed = *o.seed;
  if (o.lod) c.lod = *o.lod;
  if (o.transform) c.transform = *o.transform;
  if (o.camera) c.camera = *o.camera;
  return c;
}
}  // namespace

PolyMesh CallContext::call(std::string_view name, const NamedArgs& args, const CallOptions& options) const {
  return registry_->call(name, args, overridden(context_, options));
}

std::shared_ptr<const PolyMesh> CallContext::call_shared(std::string_view name, const NamedArgs& args,
                                                         const CallOptions& options) const {
  return registry_->call_shared(name, args, overridden(context_, options));
}

void CallContext::call_inout(std::string_view name, PolyMesh& model, const NamedArgs& args,
                             const CallOptions& options) const {
  registry_->call_inout(name, model, args, overridden(context_, options));
}

}  // namespace genmod
