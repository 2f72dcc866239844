#include "harness/scenes/params.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rotbench {

void Params::declare(std::string key, std::vector<double> value, std::string unit, std::string help) {
    entries_.push_back({std::move(key), std::move(unit), std::move(help), value, value});
}

const Params::Entry& Params::find(const std::string& key) const {
    for (const auto& e : entries_)
        if (e.key == key) return e;
    std::vector<std::string> keys;
    for (const auto& e : entries_) keys.push_back(e.key);
    throw InputError(fmt::format("unknown parameter '{}.{}'; {} has: {}", scene_id_, key, scene_id_, join(keys, ", ")));
}

void Params::set(const std::string& key, const std::vector<double>& values) {
    find(key);  // throws for an unknown key
    Entry& e = *std::find_if(entries_.begin(), entries_.end(), [&](const Entry& x) { return x.key == key; });
    require(values.size() == e.value.size(), key,
            fmt::format("expects {} value{}, got {}", e.value.size(), e.value.size() == 1 ? "" : "s", values.size()));
    for (double v : values) require(std::isfinite(v), key, "values must be finite numbers");
    e.value = values;
}

void Params::apply(const ParamOverrides& overrides) {
    for (const auto& [key, values] : overrides) set(key, values);
}

double Params::number(const std::string& key) const { return find(key).value.at(0); }

Vec3 Params::vec3(const std::string& key) const {
    const auto& v = find(key).value;
    return {v.at(0), v.at(1), v.at(2)};
}

Quat Params::quat(const std::string& key) const {
    const auto& v = find(key).value;
    const Quat q(v.at(0), v.at(1), v.at(2), v.at(3));
    require(q.norm() > 0.0, key, "the quaternion must not be zero");
    return q.normalized();
}

std::string Params::canonical() const {
    std::string out = scene_id_ + ":";
    for (const auto& e : entries_) {
        out += e.key + "=";
        for (std::size_t i = 0; i < e.value.size(); ++i) out += fmt::format("{}{}", i ? "," : "", e.value[i]);
        out += ";";
    }
    return out;
}

// Greater than 0, and a normal number: a denormal one has no finite inverse.
double Params::positive(const std::string& key) const {
    const double v = number(key);
    require(v > 0.0, key, fmt::format("must be greater than 0, got {}", v));
    require(v >= std::numeric_limits<double>::min(), key, fmt::format("{} is too small to compute with (denormal)", v));
    return v;
}

Vec3 Params::positive_vec3(const std::string& key) const {
    const Vec3 v = vec3(key);
    require(v.minCoeff() > 0.0, key, fmt::format("every component must be greater than 0, got {}, {}, {}", v.x(), v.y(), v.z()));
    require(v.minCoeff() >= std::numeric_limits<double>::min(), key,
            fmt::format("{} is too small to compute with (denormal)", v.minCoeff()));
    return v;
}

Vec3 Params::principal_moments(const std::string& key, bool real_body) const {
    const Vec3 i = positive_vec3(key);
    for (int k = 0; k < 3 && real_body; ++k)
        require(i[k] <= (i[(k + 1) % 3] + i[(k + 2) % 3]) * (1.0 + 1e-12), key,
                fmt::format("principal moments {}, {}, {} violate the triangle inequality (I{} > I{} + I{})", i.x(),
                            i.y(), i.z(), k + 1, (k + 1) % 3 + 1, (k + 2) % 3 + 1));
    return i;
}

void Params::require(bool ok, const std::string& key, const std::string& message) const {
    if (!ok) throw InputError(fmt::format("{}.{}: {}", scene_id_, key, message));
}

}  // namespace rotbench
