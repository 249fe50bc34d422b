#include "genmod/procedural/procedure_cache.hpp"

namespace genmod {

std::shared_ptr<const PolyMesh> ProcedureCache::find(const std::string& key) {
  std::lock_guard lock(mutex_);
  auto it = entries_.find(key);
  if (it == entries_.end()) {
    ++stats_.misses;
    return nullptr;
  }
  ++stats_.hits;
  recency_.splice(recency_.begin(), recency_, it->second.use);
  return it->second.mesh;
}

void ProcedureCache::insert(const std::string& key, std::shared_ptr<const PolyMesh> mesh) {
  std::lock_guard lock(mutex_);
  if (limit_ == 0 || entries_.count(key)) return;
  evict_to(limit_ - 1);
  recency_.push_front(key);
  entries_.emplace(key, Entry{std::move(mesh), recency_.begin()});
}

void ProcedureCache::evict_to(std::size_t size) {
  while (entries_.size() > size) {
    entries_.erase(recency_.back());
    recency_.pop_back();
    ++stats_.evictions;
  }
}

CacheStats ProcedureCache::stats() const {
  std::lock_guard lock(mutex_);
  CacheStats s = stats_;
  s.entries = entries_.size();
  return s;
}

void ProcedureCache::reset_stats() {
  std::lock_guard lock(mutex_);
  stats_ = {};
}

void ProcedureCache::clear() {
  std::lock_guard lock(mutex_);
  entries_.clear();
  recency_.clear();
}

void ProcedureCache::set_limit(std::size_t limit) {
  std::lock_guard lock(mutex_);
  limit_ = limit;
  evict_to(limit);
}

}  // namespace genmod
