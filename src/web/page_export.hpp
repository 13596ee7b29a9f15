#pragma once
// `mechsim view DIR --export page.html`: one self-contained HTML file with the page's script and
// every replay file it reads inlined (base64 in window.MECHSIM_EMBED), so that it opens from
// disk, offline, in any browser.

#include <filesystem>
#include <string>

#include "web/replay_folder.hpp"

namespace mechsim::web {

// The page built into `page_dir` (index.html, app.js) with `folder`'s files (which must be ok).
// Throws ViewError naming a file it cannot read or write.
void export_page(const ReplayFolder& folder, const std::filesystem::path& page_dir, const std::filesystem::path& out);

// Standard base64 (RFC 4648, with padding).
std::string base64(const std::string& bytes);

}  // namespace mechsim::web
