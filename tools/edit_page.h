/* tools/edit_page: the page of `scaf edit` (tools/edit_page.html),
 * compiled into the program by cmake/embed_file.cmake: no file to find at
 * run time, nothing to download. */
#ifndef SCAF_TOOLS_EDIT_PAGE_H
#define SCAF_TOOLS_EDIT_PAGE_H

extern const unsigned char edit_page_html[]; /* edit_page_html_len bytes, then a NUL */
extern const unsigned long edit_page_html_len;

#endif
