/* interphase drivers: what standard Fortran cannot ask the file system (POSIX stat). */
#include <sys/stat.h>

/* 1 when `path` names an existing file that is not a regular file (a device such as /dev/null,
   a directory, a named pipe, a socket; symbolic links followed), 0 otherwise (a regular file,
   or nothing there). The drivers write a CSV to CSV.part and rename it over the output: over a
   device that would replace the device node with a regular file (as root, /dev/null itself). */
int interphase_driver_is_special_file(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) return 0;
    return S_ISREG(st.st_mode) ? 0 : 1;
}

/* 1 when `path` names an existing directory (symbolic links followed), 0 otherwise. */
int interphase_driver_is_directory(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) return 0;
    return S_ISDIR(st.st_mode) ? 1 : 0;
}
