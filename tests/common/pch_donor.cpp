// SPDX-License-Identifier: GPL-3.0-or-later
// Compiles the tests' precompiled header (tests/test_precompiled_headers.cmake).
int main()
{
    return 0;
}
