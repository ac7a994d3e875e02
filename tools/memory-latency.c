/* Memory bandwidth and latency of this machine, one thread: what a pass over a scene larger than the cache can expect
   (doc/changelog.md, 2026-11-22, fifth round).

   For a buffer of MB mebibytes: the read bandwidth of a sequential sum, the read+write bandwidth of a scaled copy
   (fastest of 5 passes each), and the latency of a chain of dependent loads through the buffer's 64-byte lines in
   random order (each load's address comes from the one before, as when a loop follows pointers). With HUGE=1 in the
   environment the buffers are advised to transparent huge pages (madvise), which shortens the page walks of a
   random chain.

   cc -O2 tools/memory-latency.c -o /tmp/memory-latency && for mb in 1 2 4 16 64 512; do /tmp/memory-latency $mb; done */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <time.h>

static double now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double* buffer(size_t bytes)
{
	void* p = NULL;
	if (posix_memalign(&p, (size_t)1 << 21, bytes)) {
		fprintf(stderr, "cannot allocate %zu bytes\n", bytes);
		exit(1);
	}
	if (getenv("HUGE")) madvise(p, bytes, MADV_HUGEPAGE);
	return p;
}

int main(int argc, char** argv)
{
	const size_t mb = argc > 1 ? strtoul(argv[1], NULL, 10) : 512, n = mb * 1024 * 1024 / sizeof(double);
	if (mb < 1) {
		fprintf(stderr, "MB = %s: must be an integer >= 1\n", argv[1]);
		return 2;
	}
	double *a = buffer(n * sizeof(double)), *b = buffer(n * sizeof(double)), sum = 0, read = 1e9, copy = 1e9;
	for (size_t i = 0; i < n; i++)
		a[i] = (double)i, b[i] = 0;
	for (int pass = 0; pass < 5; pass++) {
		double t = now();
		for (size_t i = 0; i < n; i++)
			sum += a[i];
		t = now() - t;
		read = t < read ? t : read;
		t    = now();
		for (size_t i = 0; i < n; i++)
			b[i] = 1.0001 * a[i] + 1;
		t    = now() - t;
		copy = t < copy ? t : copy;
	}
	/* One pointer per 64-byte line, the lines linked in a random cyclic order (Fisher-Yates with a 64-bit LCG). */
	const size_t lines = n / 8;
	uint64_t*    next  = (uint64_t*)a;
	size_t*      order = malloc(lines * sizeof(size_t));
	uint64_t     rng   = 88172645463325252ull;
	for (size_t i = 0; i < lines; i++)
		order[i] = i;
	for (size_t i = lines - 1; i > 0; i--) {
		rng          = rng * 6364136223846793005ull + 1442695040888963407ull;
		size_t j     = (size_t)(rng >> 17) % (i + 1), x = order[i];
		order[i]     = order[j];
		order[j]     = x;
	}
	for (size_t i = 0; i < lines; i++)
		next[order[i] * 8] = order[(i + 1) % lines] * 8;
	const size_t loads = 20000000;
	size_t       at    = 0;
	double       t     = now();
	for (size_t i = 0; i < loads; i++)
		at = next[at];
	t = now() - t;
	printf("%5zu MiB%s: sequential read %.1f GB/s, scaled copy %.1f GB/s (read + write), dependent random loads %.0f ns each (%g %zu)\n", mb,
	       getenv("HUGE") ? " (huge pages)" : "", n * sizeof(double) / read / 1e9, 2 * n * sizeof(double) / copy / 1e9, t / loads * 1e9, sum + b[n / 2], at);
	return 0;
}
