#include "io/load/ModelExtensions.h"

#include <algorithm>

#include "io/import/AssimpModule.h"

namespace termshade {

std::vector<std::string> ModelFileExtensions() {
  std::vector<std::string> extensions = AssimpExtensions();
  extensions.push_back("dat");
  std::sort(extensions.begin(), extensions.end());
  extensions.erase(std::unique(extensions.begin(), extensions.end()), extensions.end());
  return extensions;
}

}  // namespace termshade
