// SPDX-License-Identifier: MIT
// error_message<Error>(work): what `work` throws as `Error`, for tests that check a message's
// text (file, line, value). Test support.
#pragma once

#include <string>

namespace exactmesh::testing {

/// The what() of the `Error` that `work()` throws, or "" when it throws none.
template <class Error, class Work>
std::string error_message(Work&& work) {
    try {
        work();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

}  // namespace exactmesh::testing
