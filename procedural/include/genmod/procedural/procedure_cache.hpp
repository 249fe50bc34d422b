// The memo table of one cacheable procedure (§1.10): canonical key bytes -> the mesh the body
// built, stored once and handed out as independent copies.
//
// Thread safety: every member locks the table's mutex; meshes are shared as immutable
// shared_ptr so copying a hit happens outside the lock. Two threads missing on the same key at
// once both run the body (both count a miss); the first insert wins and the second is dropped,
// which is harmless because bodies are deterministic.
//
// Bounded memory: at most `limit` entries; inserting into a full table evicts the least
// recently used entry (a hit refreshes an entry) and counts an eviction.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace genmod {

struct CacheStats {
  std::uint64_t hits = 0, misses = 0, evictions = 0;
  std::size_t entries = 0;
};

class ProcedureCache {
 public:
  explicit ProcedureCache(std::size_t limit) : limit_(limit) {}

  // The cached mesh for `key` (a hit), or null (a miss). Counts either.
  std::shared_ptr<const PolyMesh> find(const std::string& key);
  void insert(const std::string& key, std::shared_ptr<const PolyMesh> mesh);

  CacheStats stats() const;
  void reset_stats();
  void clear();  // drops entries, keeps counters
  void set_limit(std::size_t limit);  // limit 0 stores nothing; shrinking evicts at once

 private:
  void evict_to(std::size_t size);  // needs the lock
  struct Entry {
    std::shared_ptr<const PolyMesh> mesh;
    std::list<std::string>::iterator use;  // position in the recency list
  };
  mutable std::mutex mutex_;
  std::size_t limit_;
  std::unordered_map<std::string, Entry> entries_;
  std::list<std::string> recency_;  // most recent first
  CacheStats stats_;
};

}  // namespace genmod
