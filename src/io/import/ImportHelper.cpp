#include "io/import/ImportHelper.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <new>
#include <string>

#include "io/import/AssimpModule.h"
#include "io/import/ImportWire.h"
#include "io/import/WholeTransfer.h"

namespace termshade {

void LimitImportProcess(uint64_t addressSpaceBytes, uint64_t dataBytes, uint64_t cpuSeconds) {
  const rlimit noCore{0, 0};
  setrlimit(RLIMIT_CORE, &noCore);
  if (cpuSeconds > 0) {
    const rlimit cpu{cpuSeconds, cpuSeconds + 1};
    setrlimit(RLIMIT_CPU, &cpu);
  }
  if (addressSpaceBytes > 0 && !kAddressSanitizerBuild) {
    const rlimit space{addressSpaceBytes, addressSpaceBytes};
    setrlimit(RLIMIT_AS, &space);
  }
  if (dataBytes > 0 && !kAddressSanitizerBuild) {
    const rlimit data{dataBytes, dataBytes};
    setrlimit(RLIMIT_DATA, &data);
  }
}

int ServeImportRequest(int requestFd, int frameFd) {
  const WireSink sink = [&](const void* from, size_t size) {
    return WriteWhole(frameFd, from, size);
  };
  // Step 1: the request, whole.
  ImportRequest request;
  WireReader reader([&](void* to, size_t size) { return ReadWhole(requestFd, to, size); },
                    UINT64_MAX);
  try {
    if (!ReadRequest(reader, request)) return 1;
  } catch (const std::bad_alloc&) {
    return WriteResultFrame(ModuleStatus::kOutOfMemory, "", LoadError{}, sink) ? 0 : 1;
  }
  // Step 2: the import, its progress sent in steps of a hundredth.
  LoadOptions options;
  options.memoryBudgetBytes = request.memoryBudgetBytes;
  double lastShare = -1.0;
  bool framesOk = true;
  options.progress = [&](double share) {
    if (share < lastShare + 0.01 && !(share == 1.0 && lastShare < 1.0)) return;
    lastShare = share;
    framesOk = framesOk && WriteProgressFrame(share, sink);
  };
  ModuleStatus status = ModuleStatus::kDone;
  std::string exceptionText;
  Loaded<Mesh> result = LoadError{request.source.displayName, 0, 0, "the importer gave no result"};
  if (request.stamp != ModuleBuildStamp()) {
    result = LoadError{request.source.displayName, 0, 0,
                       "the import helper is from another build of termshade; reinstall termshade"};
  } else {
    try {
      result = ImportWithAssimp(request.source, std::move(request.bytes), options);
    } catch (const std::bad_alloc&) {
      status = ModuleStatus::kOutOfMemory;
    } catch (const std::exception& e) {
      status = ModuleStatus::kException;
      exceptionText = e.what();
    }
  }
  // Step 3: the result.
  return framesOk && WriteResultFrame(status, exceptionText, result, sink) ? 0 : 1;
}

}  // namespace termshade
