// The state of a run as bytes, for checkpoints: each part of the engine lists what it carries
// from one step to the next once, in a function `archive_state(StateArchive&)`, and that one
// list both writes the state and reads it back (so the two cannot drift apart). A part opens
// with a named section; reading checks the name, so a checkpoint of another layout fails at the
// first part that differs, by name. Values are stored as they are in memory (little-endian
// IEEE doubles on every machine sluice builds for), so a state read back is bit for bit the
// one written.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sluice {

// A state that cannot be read back (bytes missing, a section of another name).
class StateArchiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateArchive;

// A plain struct lists its members in a free function found by argument-dependent lookup:
//   void archive_state(StateArchive& a, Contact& c) { a(c.a, c.b, c.id, ...); }
template <class T>
concept ArchivedByMember = requires(T& t, StateArchive& a) {
  t.archive_state(a);
};
template <class T>
concept ArchivedByFunction = requires(T& t, StateArchive& a) {
  archive_state(a, t);
};

namespace archive_detail {

template <class T>
struct IsEigenFixed : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct IsEigenFixed<Eigen::Matrix<S, R, C, O, MR, MC>>
    : std::bool_constant<R != Eigen::Dynamic && C != Eigen::Dynamic> {};

// Values copied as their bytes: numbers, enumerations and fixed-size Eigen matrices.
template <class T>
constexpr bool kRaw = std::is_arithmetic_v<T> || std::is_enum_v<T> || IsEigenFixed<T>::value;

template <class T>
struct IsVector : std::false_type {};
template <class T, class A>
struct IsVector<std::vector<T, A>> : std::true_type {};
template <class T>
struct IsArray : std::false_type {};
template <class T, std::size_t N>
struct IsArray<std::array<T, N>> : std::true_type {};
template <class T>
struct IsPair : std::false_type {};
template <class A, class B>
struct IsPair<std::pair<A, B>> : std::true_type {};
template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <class T>
struct IsMap : std::false_type {};
template <class K, class V, class C, class A>
struct IsMap<std::map<K, V, C, A>> : std::true_type {};
template <class K, class V, class H, class E, class A>
struct IsMap<std::unordered_map<K, V, H, E, A>> : std::true_type {};

}  // namespace archive_detail

class StateArchive {
 public:
  // An archive that writes.
  StateArchive() = default;
  // An archive that reads `bytes` (which must outlive it).
  explicit StateArchive(std::string_view bytes) : input_(bytes), reading_(true) {}

  bool reading() const { return reading_; }
  // The bytes written so far; reading, how many have been read.
  const std::string& bytes() const { return output_; }
  std::size_t bytes_read() const { return read_; }

  // Opens a part: writes its name, or reads a name and checks that it is `name`.
  void section(std::string_view name);
  // Reading: every byte must have been read (else the state has parts this build lacks).
  void finish() const;

  // Each value in turn, of any supported kind (see value()).
  template <class... T>
  void operator()(T&... values) {
    (value(values), ...);
  }

  // A value that is written but, read back, only checked to be equal (the size of something
  // rebuilt from the case, say): `what` names it in the error.
  template <class T>
  void expect(const T& value, std::string_view what) {
    T stored = value;
    this->value(stored);
    if (reading_ && !(stored == value)) {
      throw StateArchiveError("the checkpoint's " + std::string(what) +
                              " differs from this case's");
    }
  }

  template <class T>
  void value(T& v) {
    using namespace archive_detail;
    if constexpr (ArchivedByMember<T>) {
      v.archive_state(*this);
    } else if constexpr (ArchivedByFunction<T>) {
      archive_state(*this, v);
    } else if constexpr (IsEigenFixed<T>::value) {
      bytes_of(v.data(), sizeof(typename T::Scalar) * T::SizeAtCompileTime);
    } else if constexpr (kRaw<T>) {
      bytes_of(&v, sizeof(T));
    } else if constexpr (std::is_same_v<T, Eigen::Quaterniond>) {
      value(v.coeffs());
    } else if constexpr (std::is_same_v<T, Eigen::VectorXd>) {
      std::uint64_t n = static_cast<std::uint64_t>(v.size());
      value(n);
      if (reading_) v.resize(static_cast<Eigen::Index>(checked_count(n, sizeof(double))));
      bytes_of(v.data(), static_cast<std::size_t>(v.size()) * sizeof(double));
    } else if constexpr (std::is_same_v<T, std::string>) {
      std::uint64_t n = v.size();
      value(n);
      if (reading_) v.resize(checked_count(n, 1));
      bytes_of(v.data(), v.size());
    } else if constexpr (IsVector<T>::value) {
      vector(v);
    } else if constexpr (IsArray<T>::value) {
      for (auto& e : v) value(e);
    } else if constexpr (IsPair<T>::value) {
      value(v.first);
      value(v.second);
    } else if constexpr (IsOptional<T>::value) {
      bool has = v.has_value();
      value(has);
      if (reading_ && has) v.emplace();
      if (reading_ && !has) v.reset();
      if (has) value(*v);
    } else if constexpr (IsMap<T>::value) {
      map(v);
    } else {
      static_assert(sizeof(T) == 0, "no archive_state for this type");
    }
  }

 private:
  void bytes_of(void* data, std::size_t size);
  // A count read back, checked against the bytes left (a corrupt count must not allocate).
  std::size_t checked_count(std::uint64_t count, std::size_t least_bytes_each) const;

  template <class T, class A>
  void vector(std::vector<T, A>& v) {
    std::uint64_t n = v.size();
    value(n);
    if constexpr (std::is_same_v<T, bool>) {
      if (reading_) v.assign(checked_count(n, 1), false);
      for (std::size_t k = 0; k < v.size(); ++k) {
        bool b = v[k];
        value(b);
        v[k] = b;
      }
    } else if constexpr (archive_detail::kRaw<T>) {
      if (reading_) v.resize(checked_count(n, sizeof(T)));
      bytes_of(v.data(), v.size() * sizeof(T));
    } else {
      if (reading_) v.resize(checked_count(n, 1));
      for (auto& e : v) value(e);
    }
  }

  // Written in key order, so that an unordered map's bytes do not depend on its buckets.
  template <class M>
  void map(M& m) {
    std::uint64_t n = m.size();
    value(n);
    if (reading_) {
      m.clear();
      for (std::size_t k = 0, count = checked_count(n, 1); k < count; ++k) {
        std::pair<typename M::key_type, typename M::mapped_type> entry;
        value(entry);
        m.emplace(std::move(entry));
      }
      return;
    }
    std::vector<typename M::key_type> keys;
    for (const auto& entry : m) keys.push_back(entry.first);
    std::sort(keys.begin(), keys.end());
    for (auto key : keys) {
      value(key);
      value(m.at(key));
    }
  }

  std::string output_;
  std::string_view input_;
  std::size_t read_ = 0;
  bool reading_ = false;
};

}  // namespace sluice
