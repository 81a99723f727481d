/* test.h: a few tiny macros for hearth's unit tests.
 *
 * Each file lists its cases with TEST_MAIN(T(a), T(b), ...). Run with a case
 * name to run just that one (meson registers each as its own test), or with
 * no argument to run them all. Exit codes: 0 pass, 1 fail, 77 expected
 * failure (meson counts it as skipped) after printing the measured number. */
#ifndef HEARTH_TEST_H
#define HEARTH_TEST_H
#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct test_case {
    const char *name;
    void (*fn)(void);
} test_case;

static int test_failures;
static int test_xfailed;

#define TEST(name) static void test_##name(void)
#define T(name) {#name, test_##name}

#define CHECK(c)                                                                                   \
    do {                                                                                           \
        if (!(c)) {                                                                                \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #c);                  \
            test_failures++;                                                                       \
        }                                                                                          \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                                      \
    do {                                                                                           \
        double a_ = (a), b_ = (b), t_ = (tol);                                                     \
        if (!(fabs(a_ - b_) <= t_)) {                                                              \
            fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.17g, %s = %.17g, |diff| = %.3g > %.3g\n", \
                    __FILE__, __LINE__, #a, a_, #b, b_, fabs(a_ - b_), t_);                        \
            test_failures++;                                                                       \
        }                                                                                          \
    } while (0)

#define CHECK_STR_CONTAINS(hay, needle)                                                            \
    do {                                                                                           \
        const char *h_ = (hay), *n_ = (needle);                                                    \
        if (!h_ || !strstr(h_, n_)) {                                                              \
            fprintf(stderr, "%s:%d: expected \"%s\" in \"%s\"\n", __FILE__, __LINE__, n_,          \
                    h_ ? h_ : "(null)");                                                           \
            test_failures++;                                                                       \
        }                                                                                          \
    } while (0)

/* Mark the running case as an expected failure: prints the measured number and why. */
#define XFAIL(...)                                                                                 \
    do {                                                                                           \
        printf("EXPECTED FAILURE: ");                                                              \
        printf(__VA_ARGS__);                                                                       \
        printf("\n");                                                                              \
        test_xfailed = 1;                                                                          \
    } while (0)

static inline int test_run(const test_case *cases, int n, int argc, char **argv) {
    int ran = 0;
    for (int i = 0; i < n; i++) {
        if (argc > 1 && strcmp(argv[1], cases[i].name) != 0) continue;
        int before = test_failures;
        cases[i].fn();
        ran++;
        printf("%-40s %s\n", cases[i].name, test_failures > before ? "FAIL" : "ok");
        fflush(stdout);
    }
    if (ran == 0) {
        fprintf(stderr, "no test named '%s'\n", argc > 1 ? argv[1] : "");
        return 1;
    }
    if (test_failures) return 1;
    return test_xfailed ? 77 : 0;
}

#define TEST_MAIN(...)                                                                             \
    int main(int argc, char **argv) {                                                              \
        static const test_case cases_[] = {__VA_ARGS__};                                           \
        return test_run(cases_, (int)(sizeof cases_ / sizeof cases_[0]), argc, argv);              \
    }
#endif
