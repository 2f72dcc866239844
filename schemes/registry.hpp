// A registry of named factories, filled by static registration objects, so that adding
// a scheme or a scene is one source file (the Google Benchmark pattern).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace rotbench {

// Thrown for input the user can fix (unknown id, bad number, ...): the CLI turns it into
// one line on stderr and exit status 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline std::string join(const std::vector<std::string>& items, const std::string& sep) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? sep : "") + items[i];
    return out;
}

// `Extra`: what else an entry states about itself (a scheme's claims, schemes/scheme.hpp).
template <class Product, class Extra = std::monostate>
class Registry {
public:
    struct Entry {
        std::string id;
        std::string summary;   // one line for `rotbench list`
        std::string source;    // citation: paper and equations
        std::string notes;     // choices made where the source leaves one open (for the report)
        std::function<std::unique_ptr<Product>()> make;
        Extra extra{};
    };

    static Registry& instance() {
        static Registry registry;
        return registry;
    }

    void add(Entry entry) {
        const std::string id = entry.id;
        if (!entries_.emplace(id, std::move(entry)).second)
            throw std::logic_error("duplicate registration of '" + id + "'");
    }

    const Entry& at(const std::string& id, const std::string& kind) const {
        auto it = entries_.find(id);
        if (it == entries_.end())
            throw InputError("unknown " + kind + " '" + id + "'; valid " + kind + "s: " + join(ids(), ", "));
        return it->second;
    }

    bool contains(const std::string& id) const { return entries_.count(id) != 0; }

    std::vector<std::string> ids() const {
        std::vector<std::string> out;
        for (const auto& [id, entry] : entries_) out.push_back(id);
        return out;
    }

private:
    std::map<std::string, Entry> entries_;  // ordered: listings and sweeps are deterministic
};

}  // namespace rotbench
