/// \file
/// A fixture for `api_docs_catches_undocumented`: the reference's Doxygen settings must fail on
/// it (an undocumented function, and a documented one whose parameter and return value are not).
#pragma once

namespace fixture {

int undocumented_function(int x);

/// Documented, but without its parameter and return value.
int half_documented_function(int x);

}  // namespace fixture
