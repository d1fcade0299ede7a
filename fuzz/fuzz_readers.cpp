// libFuzzer harness: one reader per build, chosen by HEXDUAL_FUZZ_TARGET (see fuzz/run.sh).
// Every input must either read or throw hexdual::Error; anything else (crash, sanitizer report,
// other exception) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "complex/builders.hpp"
#include "complex/complex.hpp"
#include "io/inflate.hpp"
#include "io/io.hpp"
#include "ops/oplog.hpp"

using namespace hexdual;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view in(reinterpret_cast<const char*>(data), size);
  try {
#if HEXDUAL_FUZZ_TARGET == 1
    io::readVtk(in, "f.vtk");
#elif HEXDUAL_FUZZ_TARGET == 2
    io::readVtu(in, "f.vtu");
#elif HEXDUAL_FUZZ_TARGET == 3
    io::readGmsh(in, "f.msh");
#elif HEXDUAL_FUZZ_TARGET == 4
    io::readMedit(in, "f.mesh");
#elif HEXDUAL_FUZZ_TARGET == 5
    io::readMeditBinary(in, "f.meshb");
#elif HEXDUAL_FUZZ_TARGET == 6
    io::readNative(in, "f.hxd");
#elif HEXDUAL_FUZZ_TARGET == 7
    io::inflateRaw(in, size_t(1) << 24);
    io::gunzip(in, size_t(1) << 24);
    io::inflateZlib(in, size_t(1) << 24);
#elif HEXDUAL_FUZZ_TARGET == 8
    // Parse both forms; a parsed log must survive formatting and the URL round trip, and applying
    // its steps to a small grid must either work or throw Error.
    for (int form = 0; form < 2; ++form) {
      OpLog log;
      try {
        log = form ? decodeOpLogUrl(in) : parseOpLog(in);
      } catch (const Error&) {
        continue;
      }
      parseOpLog(formatOpLog(log));
      decodeOpLogUrl(encodeOpLogUrl(log));
      Complex cx = makeGrid(2, 2, 2);
      for (size_t k = 0; k < log.steps.size() && k < 8; ++k) try {
          applyStep(cx, formatOpStep(log.steps[k]));
        } catch (const Error&) {
        }
    }
#else
#error "define HEXDUAL_FUZZ_TARGET"
#endif
  } catch (const Error&) {
  }
  return 0;
}
