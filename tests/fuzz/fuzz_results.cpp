// libFuzzer target: the readers of rotbench's own CSV files, which a user may hand back edited,
// cut or forged (`report DIR`, `merge`, `gate --results`, `run --resume`): results.csv, runs.csv
// and an energy series (the input's parts, split at form feeds), and the run store's records (journal, worker).
#include "harness/io/results_csv.hpp"
#include "harness/io/run_record.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace rotbench;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input = fuzz::text(data, size);
    std::string parts[3];
    for (std::size_t part = 0, begin = 0; part < 3 && begin <= input.size(); ++part) {
        const std::size_t end = part == 2 ? input.size() : std::min(input.find('\f', begin), input.size());
        parts[part] = input.substr(begin, end - begin);
        begin = end + 1;
    }
    fuzz::parse_or_input_error([&] { parse_results(parts[0], parts[1], {{"series/energy_fibre_bounce_direct_dt1e-06.csv", parts[2]}}, "fuzz"); });
    fuzz::parse_or_input_error([&] { parse_run_records(input, "fuzz/partial/runs.jsonl"); });
    return 0;
}
