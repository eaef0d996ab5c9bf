// SPDX-License-Identifier: MIT
// Temporary files and folders tied to the process that made them: their name
// carries its process id (`<prefix><pid>`, then the end of the name or a
// character that is not a digit), so that what a killed process left behind
// (an interrupted write's temporary, a `doc new` database and its -wal/-shm,
// the STEP/IGES exchange's scratch folder, a campaign's study copies) is
// recognised and removed by the next run, and nothing else is.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace hula::io {

/// `<prefix><pid of this process>`: the start of the name of a temporary this
/// process owns (append "-XXXXXX" for mkstemp/mkdtemp, or an index).
[[nodiscard]] std::string owned_name(std::string_view prefix);

/// Removes the entries of `dir` whose owner is gone: names `<prefix><pid>`
/// followed by the end or a non-digit, owned by this user, whose process `pid`
/// no longer exists, is a zombie, or started over a second after the entry
/// was last modified (the id was reused). Entries of live owners (this process included), names that do not
/// parse, other users' entries and symbolic links are left alone; a directory
/// is removed with its contents (links inside it are removed, not followed).
/// Errors (a vanished entry, an unreadable `dir`) are ignored: the cleaning is
/// best effort and never fails the command that does it.
void remove_orphaned(const std::filesystem::path& dir, std::string_view prefix) noexcept;

}  // namespace hula::io
