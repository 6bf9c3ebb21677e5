/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The Unity suite of the C++ layer (tests/cxx/test_cxx.cpp).
 */
#ifndef TEST_CXX_H
#define TEST_CXX_H

/** Run every test of drdc.hpp. */
void suite_cxx(void);

#endif /* TEST_CXX_H */
