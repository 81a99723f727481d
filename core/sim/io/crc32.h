/* crc32.h: CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320), the
 * checksum of checkpoint files. Chosen over xxhash64 for having one obvious
 * reference (zlib's crc32 gives the same numbers) and no seed to record; its
 * speed (a table lookup per byte, ~0.5 GB/s) is far above the disk's. */
#ifndef HEARTH_CRC32_H
#define HEARTH_CRC32_H
#include <stddef.h>
#include <stdint.h>

/// Continue a CRC-32 over n more bytes. Start with crc = 0; the result of
/// crc32_update(crc32_update(0, a, na), b, nb) is the CRC of a followed by b.
uint32_t crc32_update(uint32_t crc, const void *data, size_t n);
#endif
