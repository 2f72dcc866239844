#include "harness/store/scheme_record.hpp"

#include "harness/store/client.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/plugin.hpp"

#include <nlohmann/json.hpp>

namespace rotbench {
namespace {

using json = nlohmann::json;

json to_json(const SchemeInfo& s) {
    const SchemeClaims& c = s.claims;
    return {{"summary", s.summary},
            {"source", s.source},
            {"notes", s.notes},
            {"claims",
             {{"without_torque", {{"order", c.without_torque.order}, {"reason", c.without_torque.reason}}},
              {"with_torque", {{"order", c.with_torque.order}, {"reason", c.with_torque.reason}}},
              {"exact_without_torque", c.exact_without_torque},
              {"conserves_momentum", c.conserves_momentum},
              {"bounded_energy", c.bounded_energy},
              {"time_reversible", c.time_reversible},
              {"sound", c.sound},
              {"family", c.family},
              {"declared_at", c.declared_at}}},
            {"client", s.client},
            {"counterpart", s.counterpart},
            {"counterpart_note", s.counterpart_note},
            {"plugin", {{"path", s.plugin_path}, {"hash", s.plugin_hash}, {"build", s.plugin_build}}},
            {"client_files", {{"path", s.client_file}, {"hash", s.client_hash}, {"program_hash", s.program_hash}}}};
}

// A claimed order: a small whole number (a float, or one past int, would convert with undefined behaviour).
int order_of(const json& j) {
    if (!j.is_number_integer() || j.get<long long>() < 0 || j.get<long long>() > 100) throw InputError("a claimed order must be 0 to 100");
    return static_cast<int>(j.get<long long>());
}

SchemeInfo from_json(const std::string& id, const json& j) {
    SchemeInfo s;
    s.id = id;
    j.at("summary").get_to(s.summary), j.at("source").get_to(s.source), j.at("notes").get_to(s.notes);
    const json& c = j.at("claims");
    s.claims.without_torque.order = order_of(c.at("without_torque").at("order"));
    c.at("without_torque").at("reason").get_to(s.claims.without_torque.reason);
    s.claims.with_torque.order = order_of(c.at("with_torque").at("order"));
    c.at("with_torque").at("reason").get_to(s.claims.with_torque.reason);
    c.at("exact_without_torque").get_to(s.claims.exact_without_torque);
    c.at("conserves_momentum").get_to(s.claims.conserves_momentum);
    c.at("bounded_energy").get_to(s.claims.bounded_energy);
    c.at("time_reversible").get_to(s.claims.time_reversible);
    c.at("sound").get_to(s.claims.sound);
    c.at("family").get_to(s.claims.family);
    c.at("declared_at").get_to(s.claims.declared_at);
    j.at("client").get_to(s.client), j.at("counterpart").get_to(s.counterpart), j.at("counterpart_note").get_to(s.counterpart_note);
    const json& p = j.at("plugin");
    p.at("path").get_to(s.plugin_path), p.at("hash").get_to(s.plugin_hash), p.at("build").get_to(s.plugin_build);
    const json& f = j.at("client_files");
    f.at("path").get_to(s.client_file), f.at("hash").get_to(s.client_hash), f.at("program_hash").get_to(s.program_hash);
    return s;
}

}  // namespace

SchemeInfo scheme_info(const std::string& id) {
    const auto& e = SchemeRegistry::instance().at(id, "scheme");
    SchemeInfo s{e.id, e.summary, e.source, e.notes, e.extra};
    if (const LoadedClient* client = client_of(id)) {
        s.client = true, s.counterpart = client->counterpart, s.counterpart_note = client->counterpart_note;
        s.client_file = client->path, s.client_hash = client->hash, s.program_hash = client->program_hash;
    }
    if (const LoadedPlugin* plugin = plugin_of(id)) s.plugin_path = plugin->path, s.plugin_hash = plugin->hash, s.plugin_build = plugin->build;
    return s;
}

SchemeInfos describe_schemes(const std::vector<std::string>& ids, const SchemeInfos& recorded) {
    SchemeInfos out;
    for (const auto& id : ids) {
        if (out.count(id)) continue;
        if (SchemeRegistry::instance().contains(id)) out[id] = scheme_info(id);
        else if (const auto it = recorded.find(id); it != recorded.end()) out[id] = it->second;
    }
    return out;
}

std::string schemes_json(const SchemeInfos& schemes) {
    json j = json::object();
    for (const auto& [id, s] : schemes) j[id] = to_json(s);
    return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

SchemeInfos parse_schemes_json(const std::string& text, const std::string& name) {
    try {
        const json all = json::parse(text);
        if (!all.is_object()) throw InputError(name + ": not a schemes.json rotbench wrote: not an object");
        SchemeInfos out;
        for (const auto& [id, j] : all.items()) {
            if (!is_id(id)) throw InputError("'" + id + "' is not a scheme id");
            out[id] = from_json(id, j);
        }
        return out;
    } catch (const json::exception& e) {
        throw InputError(name + ": not a schemes.json rotbench wrote: " + e.what());
    } catch (const InputError& e) {
        throw InputError(name + ": not a schemes.json rotbench wrote: " + e.what());
    }
}

SchemeInfos read_schemes(const std::filesystem::path& dir) {
    const std::filesystem::path file = dir / "schemes.json";
    if (!std::filesystem::exists(std::filesystem::symlink_status(file))) return {};
    return parse_schemes_json(read_input_file(file, "cannot read"), file.string());
}

}  // namespace rotbench
