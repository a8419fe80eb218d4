/* tools/edit_page: the page of `scaf edit` (tools/edit_page.html),
 * compiled into the program by cmake/embed_file.cmake: no file to find at
 * run time, nothing to download. */
#ifndef SCAF_TOOLS_EDIT_PAGE_H
#define SCAF_TOOLS_EDIT_PAGE_H

extern const unsigned char edit_page_html[]; /* edit_page_html_len bytes, then a NUL */
extern const unsigned long edit_page_html_len;
/* its second script (tools/edit_page_tools.js), compiled in the same way */
extern const unsigned char edit_page_tools_js[];
extern const unsigned long edit_page_tools_js_len;
/* three.js for its 3D view (Debian's libjs-three at build time); length 0
 * when the build had none */
extern const unsigned char edit_three_js[];
extern const unsigned long edit_three_js_len;

#endif
