// The section "Block contacts" of docs/performance.md.
#pragma once

#include "bench/contacts.h"

#include <filesystem>
#include <string>

namespace jl::bench {

std::string contactsSection(const ContactsStudy& s, bool quick, bool& ok);
// DIR/contacts_broad_phase.csv and DIR/contacts_examples.csv.
bool writeContactsCsv(const ContactsStudy& s, const std::filesystem::path& dir);
// The section alone (jladder bench --only contacts).
bool writeContactsReport(const ContactsStudy& s, bool quick, const std::filesystem::path& report);

}  // namespace jl::bench
