// Registered procedures (Morkel ch. 3 as an embedded C++ API; §1.12 of the spec): a procedure
// has a name, a mode (Out builds a new PolyMesh, InOut changes the given one), typed parameters
// each with a mandatory default, an optional bounding box, a cacheable flag and a body. Calls
// name their arguments in any order; missing ones take their defaults; the context (seed,
// transform, level of detail) passes to callees unchanged unless a call overrides it.
//
// Argument types must match the declaration, with one explicit conversion: an Integer given
// for a Double parameter is converted when it is exactly representable (|v| <= 2^53), and the
// converted value is what the body and the cache key see. Nothing else converts.
//
// Level of detail and lazy evaluation (section 1.8, camera.hpp): a call whose context has a
// camera, of a procedure that declares bounds, first places the bounds by the context's
// transform. If the camera does not see them the body is not run at all: an Out call returns
// an empty mesh, an InOut call leaves the model as it was, nothing is looked up in or added to
// the cache, and culled_calls counts it. Otherwise the camera's level (view_of_box) replaces
// the context's lod for this call and its callees. Without a camera, or without bounds, the lod
// is the inherited one (0 unless a caller set it). A camera is checked (check_camera) by every
// call that carries one; bounds that are not a finite box (lo <= hi) and a non-finite transform
// are refused when a camera reads them. The camera itself is not in the cache key: only the lod
// it chose is, for procedures with uses_lod.
//
// Threads: register every procedure before calling from several threads; calls (and the cache
// queries / switches) are then safe from any number of threads (e.g. TBB tasks).
#pragma once

#include "genmod/procedural/affine.hpp"
#include "genmod/procedural/camera.hpp"
#include "genmod/procedural/param_value.hpp"
#include "genmod/procedural/poly_mesh.hpp"
#include "genmod/procedural/procedure_cache.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace genmod {

// Unset exists so that a spec that forgets its mode is refused (claim 4), as the grammar does.
enum class Mode { Unset, Out, InOut };

struct ParamDecl {
  std::string name;
  ParamType type = ParamType::Double;
  std::optional<ParamValue> default_value;  // mandatory: registration refuses none
};
// A parameter whose type is its default's.
ParamDecl param(std::string name, ParamValue default_value);

// The predefined parameters (§1.5), passed implicitly to every callee.
struct Context {
  std::int64_t seed = 0;
  Affine transform;
  int lod = 0;  // a refinement offset: 0 = as the parameters say, below 0 coarser (camera.hpp)
  std::optional<Camera> camera = std::nullopt;  // none: no culling, the lod as given
};

// Per-call overrides of the inherited context.
struct CallOptions {
  std::optional<std::int64_t> seed;
  std::optional<int> lod;
  std::optional<Affine> transform;
  std::optional<Camera> camera;
};

using NamedArgs = std::vector<std::pair<std::string, ParamValue>>;
class ProcedureRegistry;
struct ProcedureSpec;

// The resolved arguments of one call, in declaration order, read by name.
class Arguments {
 public:
  Arguments(const ProcedureSpec* spec, std::vector<ParamValue> values) : spec_(spec), values_(std::move(values)) {}
  const ParamValue& operator[](std::string_view name) const;
  double real(std::string_view name) const { return (*this)[name].as_double(); }
  std::int64_t integer(std::string_view name) const { return (*this)[name].as_integer(); }
  bool boolean(std::string_view name) const { return (*this)[name].as_bool(); }
  const std::string& string(std::string_view name) const { return (*this)[name].as_string(); }
  const Vec3& vector(std::string_view name) const { return (*this)[name].as_vector(); }
  const std::vector<ParamValue>& values() const { return values_; }

 private:
  const ProcedureSpec* spec_;
  std::vector<ParamValue> values_;
};

// What a body sees besides its arguments: the context, and calls to other procedures that
// inherit it (Morkel's rewritten #Proc calls).
class CallContext {
 public:
  CallContext(const ProcedureRegistry& registry, Context context) : registry_(&registry), context_(context) {}
  const Context& context() const { return context_; }
  std::int64_t seed() const { return context_.seed; }
  int lod() const { return context_.lod; }
  const Affine& transform() const { return context_.transform; }
  const std::optional<Camera>& camera() const { return context_.camera; }
  PolyMesh call(std::string_view name, const NamedArgs& args = {}, const CallOptions& options = {}) const;
  // The same call for a part the body only reads (appends, measures): see
  // ProcedureRegistry::call_shared.
  std::shared_ptr<const PolyMesh> call_shared(std::string_view name, const NamedArgs& args = {},
                                              const CallOptions& options = {}) const;
  void call_inout(std::string_view name, PolyMesh& model, const NamedArgs& args = {},
                  const CallOptions& options = {}) const;

 private:
  const ProcedureRegistry* registry_;
  Context context_;
};

using OutBody = std::function<PolyMesh(const Arguments&, const CallContext&)>;
using InOutBody = std::function<void(PolyMesh&, const Arguments&, const CallContext&)>;
using BoundsFn = std::function<std::array<Vec3, 2>(const Arguments&)>;

struct ProcedureSpec {
  std::string name;
  Mode mode = Mode::Unset;
  std::vector<ParamDecl> params;
  std::optional<BoundsFn> bounds;  // the cheap bounding volume of §1.8, local frame
  bool cacheable = false;
  // Which context entries change the geometry, and so join the cache key (the seed always
  // does, as in the thesis).
  bool uses_lod = false;
  bool uses_transform = false;
  OutBody out_body;      // for Mode::Out
  InOutBody inout_body;  // for Mode::InOut
};

// The thesis's signature comment: "OUT:Double,ratio:Integer,arms:String,name" (claim 5).
std::string signature_string(const ProcedureSpec& spec);

class ProcedureRegistry {
 public:
  explicit ProcedureRegistry(std::size_t default_cache_limit = 1024) : default_cache_limit_(default_cache_limit) {}
  ProcedureRegistry(const ProcedureRegistry&) = delete;
  ProcedureRegistry& operator=(const ProcedureRegistry&) = delete;

  // Throws std::invalid_argument (naming the procedure and the parameter) for: an empty or
  // duplicate procedure name, no mode, no body for the mode, a parameter without a default,
  // a default of another type than declared, a duplicate parameter name.
  void add(ProcedureSpec spec);
  bool contains(std::string_view name) const;
  const ProcedureSpec& spec(std::string_view name) const;
  std::string signature(std::string_view name) const { return signature_string(spec(name)); }

  // The arguments a call would see. Throws std::invalid_argument naming the procedure and the
  // parameter for an unknown name, a repeated name or a wrong type.
  Arguments resolve(std::string_view name, const NamedArgs& args) const;
  std::optional<std::array<Vec3, 2>> bounds(std::string_view name, const NamedArgs& args = {}) const;

  // Top-level calls; bodies call through their CallContext instead.
  PolyMesh call(std::string_view name, const NamedArgs& args = {}, const Context& context = {}) const;
  // The same call (same result bytes, same hit and miss counts), but the mesh is shared and
  // read-only: a cache hit hands out the stored mesh itself instead of a deep copy. The copy of
  // a hit is what Experiment 6's warm calls cost (§4.6: "dominated by deep-copying"), and an
  // assembling body (the luggage appending 30 legs) copies the part again anyway. Hits stay
  // independent (claim 10) because nobody can change a const mesh; use call() for a mesh to edit.
  std::shared_ptr<const PolyMesh> call_shared(std::string_view name, const NamedArgs& args = {},
                                              const Context& context = {}) const;
  void call_inout(std::string_view name, PolyMesh& model, const NamedArgs& args = {},
                  const Context& context = {}) const;

  // The registry-wide caching switch (on by default); off means no lookups and no inserts.
  void set_caching(bool on) { caching_.store(on); }
  bool caching() const { return caching_.load(); }
  CacheStats cache_stats(std::string_view name) const;
  void reset_cache_stats(std::string_view name) const;
  void set_cache_limit(std::string_view name, std::size_t limit) const;
  void clear_caches() const;  // drops every entry of every procedure, counters stay
  // Calls of `name` that the camera culled (lazy evaluation), since registration.
  std::uint64_t culled_calls(std::string_view name) const;

 private:
  struct Entry {
    ProcedureSpec spec;
    std::unique_ptr<ProcedureCache> cache;
    std::unique_ptr<std::atomic<std::uint64_t>> culled = std::make_unique<std::atomic<std::uint64_t>>(0);
  };
  const Entry& entry(std::string_view name) const;
  // The context a call runs in (the camera's lod applied), or none when the camera culls it.
  std::optional<Context> in_view(const Entry& entry, const Arguments& args, Context context) const;
  std::string cache_key(const Entry& entry, const Arguments& args, const Context& context,
                        const PolyMesh* input) const;
  std::map<std::string, Entry, std::less<>> procedures_;
  std::size_t default_cache_limit_;
  std::atomic<bool> caching_{true};
};

}  // namespace genmod
