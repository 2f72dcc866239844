// Template part of harness/toml_input.hpp.
#include "harness/store/parse.hpp"

namespace rotbench {

template <class Product, class Extra>
std::vector<std::string> ids(const std::string& path, const std::string& key, const toml::node& node,
                             const Registry<Product, Extra>& registry, const std::string& kind) {
    try {
        return parse_id_list(join(strings(path, key, node), ","), registry, kind);
    } catch (const InputError& e) {
        if (std::string(e.what()).rfind(path, 0) == 0) throw;
        toml_error(path, node, e.what());
    }
}

}  // namespace rotbench
