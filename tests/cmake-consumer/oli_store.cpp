// SPDX-License-Identifier: MIT
// HulaHoops::oli_store alone (SQLite reached through the package): a document file is created, one
// batch writes an entity, and the file reopened read-only gives it back with the revision.
#include <cstdio>
#include <filesystem>

#include "hula/oli/store/store.hpp"

int main(int argc, char** argv) {
  namespace store = hula::oli::store;
  const std::filesystem::path dir = argc > 2 ? argv[2] : std::filesystem::temp_directory_path();
  const std::filesystem::path file = dir / "consumer-store.hula";
  std::filesystem::remove(file);
  {
    store::Store s = store::Store::create(file, {.backend = "native", .tool_version = "consumer"}, false);
    store::Batch b;
    b.entities.push_back({1, store::Blob("curve state")});
    b.revision = 1;
    b.next_label = 2;
    s.apply(b);
  }
  const store::Store s = store::Store::open(file, store::Access::ReadOnly);
  const store::Snapshot snap = s.load();
  const bool ok = snap.document.revision == 1 && snap.document.next_label == 2 && snap.entities.size() == 1 &&
                  snap.entities[0].second == "curve state" && s.integrity_check().empty();
  std::printf("oli_store: schema %d, revision %llu, %zu entity\n", snap.schema_version,
              static_cast<unsigned long long>(snap.document.revision), snap.entities.size());
  return ok ? 0 : 1;
}
