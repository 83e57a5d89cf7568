#pragma once

#include <cstdint>

namespace termshade {

/// Sets this process's limits for one import: address space and data (heap
/// and private writable mappings: what the importer allocates; neither in
/// AddressSanitizer builds, which reserve terabytes; 0: none), processor
/// seconds (SIGXCPU at the limit, SIGKILL a second later) and no core files.
void LimitImportProcess(uint64_t addressSpaceBytes, uint64_t dataBytes, uint64_t cpuSeconds);

/// The import helper's work (termshade-import, io/import/IsolatedImport.h): reads
/// one request from requestFd, imports it with Assimp in this process (the
/// module), writes progress frames and then the result frame to frameFd
/// (io/import/ImportWire.h). Returns the exit status: 0 once the result is written,
/// 1 when the request could not be read or the frames not written.
int ServeImportRequest(int requestFd, int frameFd);

}  // namespace termshade
