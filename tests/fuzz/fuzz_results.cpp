// libFuzzer target: the reader of rotbench's run store, which a user may hand back edited, cut
// or forged (`report DIR`, `merge`, `compare`, `gate --results`, `run --resume`), and which an
// isolated worker's output is read with: runs.jsonl and the journal's records.
#include "harness/store/results_csv.hpp"
#include "harness/store/run_record.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace rotbench;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input = fuzz::text(data, size);
    fuzz::parse_or_input_error([&] { parse_run_store(input, "fuzz/runs.jsonl"); });
    fuzz::parse_or_input_error([&] { parse_run_records(input, "fuzz/partial/runs.jsonl"); });
    return 0;
}
