#include "arrays.hpp"

#include <cmath>
#include <stdexcept>

namespace py = pybind11;

namespace genmod::python {

std::vector<Interval> box_from_array(const DoubleArray& a, const std::string& what) {
  if (a.ndim() != 2 || a.shape(1) != 2)
    throw std::invalid_argument(what + " must be an array of shape (n, 2) of [lo, hi] rows");
  std::vector<Interval> box;
  for (py::ssize_t k = 0; k < a.shape(0); ++k) {
    const double lo = a.at(k, 0), hi = a.at(k, 1);
    if (!(lo <= hi)) throw std::invalid_argument(what + ": row " + std::to_string(k) + " is not an interval lo <= hi");
    box.emplace_back(lo, hi);
  }
  return box;
}

Interval interval_from_array(const DoubleArray& a, const std::string& what) {
  if (a.ndim() != 1 || a.shape(0) != 2) throw std::invalid_argument(what + " must be a pair [lo, hi]");
  const double lo = a.at(0), hi = a.at(1);
  if (!(lo <= hi)) throw std::invalid_argument(what + " is not an interval lo <= hi");
  return Interval(lo, hi);
}

std::vector<double> vector_from_array(const DoubleArray& a, std::size_t n, const std::string& what) {
  if (a.ndim() != 1 || (n != 0 && static_cast<std::size_t>(a.shape(0)) != n))
    throw std::invalid_argument(what + " must be an array of shape (" + (n ? std::to_string(n) : "n") + ",)");
  std::vector<double> v(a.data(), a.data() + a.shape(0));
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k])) throw std::invalid_argument(what + ": entry " + std::to_string(k) + " is not finite");
  return v;
}

std::array<double, 3> point3_from_array(const DoubleArray& a, const std::string& what) {
  const std::vector<double> v = vector_from_array(a, 3, what);
  return {v[0], v[1], v[2]};
}

py::array_t<double> to_array(const Interval& x) {
  py::array_t<double> r(py::ssize_t{2});
  r.mutable_at(0) = x.lo();
  r.mutable_at(1) = x.hi();
  return r;
}

py::array_t<double> to_array(std::span<const Interval> box) {
  py::array_t<double> r({static_cast<py::ssize_t>(box.size()), py::ssize_t{2}});
  for (std::size_t k = 0; k < box.size(); ++k) {
    r.mutable_at(k, 0) = box[k].lo();
    r.mutable_at(k, 1) = box[k].hi();
  }
  return r;
}

py::array_t<double> to_array(std::span<const double> values) {
  py::array_t<double> r(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), r.mutable_data());
  return r;
}

py::array_t<double> boxes_to_array(const std::vector<std::vector<Interval>>& boxes, std::size_t n) {
  py::array_t<double> r({static_cast<py::ssize_t>(boxes.size()), static_cast<py::ssize_t>(n), py::ssize_t{2}});
  for (std::size_t b = 0; b < boxes.size(); ++b)
    for (std::size_t k = 0; k < n; ++k) {
      r.mutable_at(b, k, 0) = boxes[b][k].lo();
      r.mutable_at(b, k, 1) = boxes[b][k].hi();
    }
  return r;
}

}  // namespace genmod::python
