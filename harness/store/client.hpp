// `--client FILE`: a scheme that runs outside rotbench, in a program of its own (a DEM or MD
// code behind a small adapter, docs/clients.md). The client file (TOML) says how to start the
// program and what the scheme claims; loading it adds the scheme to the registry, where it is
// swept, gated, reported and compared like any other, its runs made by the program
// (harness/exec/client_run.hpp). Errors name the file, line and column (InputError).
//
//   id          = "lammps_rigid_nve"                 # letters, digits, underscores; new to the registry
//   summary     = "LAMMPS fix rigid/nve"
//   program     = ["python3", "{dir}/adapter.py", "--fix", "rigid/nve"]   # an argument vector, never a shell;
//                                                      # {dir} is the client file's folder
//   scenes      = ["asymmetric_free", "dipole_top"]  # the scenes it can take
//   claims      = "no_squish"                        # a built-in scheme's claims, or a table [claims]
//   sound       = false                              # optional: a code known to be wrong ...
//   unsound_reason = "..."                           # ... and why (required with sound = false)
//   counterpart = "no_squish"                        # optional: the built-in scheme it should equal, or a
//                                                    # client loaded before it (another version of the code) ...
//   counterpart_note = "..."                         # ... and, where it does not, why (for the report)
//
//   [claims]                                          # instead of claims = "id"; every key optional
//   order_without_torque = 2
//   order_with_torque = 2
//   exact_without_torque = false
//   conserves_momentum = true
//   bounded_energy = true
//
// A client is never run backwards: a built-in's claim of time reversibility is not taken over.
#pragma once

#include <string>
#include <vector>

namespace rotbench {

struct LoadedClient {
    std::string id;
    std::string path;                  // absolute
    std::string hash;                  // FNV-1a of the file's bytes, hex
    std::vector<std::string> program;  // {dir} replaced
    std::string program_hash;          // FNV-1a of the files the program names (interpreter, script), hex
    std::vector<std::string> scenes;
    std::string counterpart;           // empty: none
    std::string counterpart_note;      // why it is not the counterpart's map, where it is not
};

// Loads the file and registers its scheme; returns its id.
std::string load_client(const std::string& path);
const std::vector<LoadedClient>& loaded_clients();
// The client a scheme came from, or nullptr.
const LoadedClient* client_of(const std::string& scheme);
// Why the scheme cannot run on the scene (a client whose file does not list it), or empty:
// planners skip such a pair and say so, never silently.
std::string why_not_taken(const std::string& scheme, const std::string& scene);

}  // namespace rotbench
