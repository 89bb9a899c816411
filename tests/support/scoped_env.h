// SPDX-License-Identifier: Apache-2.0
// An environment variable set for one scope (CMFILTER_MEMORY_LIMIT, OCIO),
// restored after.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>

namespace cmfilter_test {

class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name)
    {
        if (const char* old = std::getenv(name)) old_ = old;
        setenv(name, value, 1);
    }
    ~ScopedEnv()
    {
        if (old_) setenv(name_, old_->c_str(), 1);
        else unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

}  // namespace cmfilter_test
