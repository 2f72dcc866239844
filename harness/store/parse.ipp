// Template part of harness/parse.hpp.
#include <algorithm>

namespace rotbench {

template <class Product, class Extra>
std::vector<std::string> parse_id_list(const std::string& text, const Registry<Product, Extra>& registry,
                                       const std::string& kind) {
    std::vector<std::string> ids;
    for (const std::string& id : split_commas(text)) {
        if (id.empty()) throw InputError("empty " + kind + " id in '" + text + "'");
        registry.at(id, kind);  // throws with the list of valid ids
        if (std::find(ids.begin(), ids.end(), id) != ids.end())
            throw InputError(kind + " '" + id + "' is given twice");
        ids.push_back(id);
    }
    return ids;
}

}  // namespace rotbench
