/* alloc.h: the one allocation path of libhearth (style rule 6).
 * Every block is counted so hearth_bytes_allocated() and `hearth bench`
 * can report bytes per particle. Tests can make the Nth allocation fail. */
#ifndef HEARTH_SIM_ALLOC_H
#define HEARTH_SIM_ALLOC_H
#include <stddef.h>

/// Allocate n bytes; NULL only on failure (n == 0 gives a non-NULL empty
/// block that holds nothing and costs nothing: zero bytes are not out of memory).
void *mem_alloc(size_t n);
/// Allocate n zeroed bytes.
void *mem_calloc(size_t n);
/// Grow or shrink p (NULL or an empty block for none) from osize to nsize
/// bytes; on failure p is untouched and NULL returned; nsize 0 frees p and
/// gives an empty block.
void *mem_realloc(void *p, size_t osize, size_t nsize);
/// Free p of size n (NULL and the empty block are fine).
void mem_free(void *p, size_t n);
/// Duplicate a string (counted).
char *mem_strdup(const char *s);
void mem_strfree(char *s);

/// A size in decimal megabytes or gigabytes for a message: "2.19 MB", "231 GB".
void mem_size_words(char *buf, size_t n, double bytes);
/// The memory ceiling (hearth_memory_limit) in words for a message: "64 MiB = 67.1 MB", "12.6 GB".
void mem_limit_words(char *buf, size_t n);

/// Testing: make the allocation after `n` more succeed calls fail (n < 0 disables).
void mem_fail_after(long n);
#endif
