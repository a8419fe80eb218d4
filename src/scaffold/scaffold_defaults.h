/* scaffold/scaffold_defaults: the default scaffold, named once.
 *
 * The box around the charts is 3 times their UV bounding box, each box
 * side carries 5 points (one corner included), and the scaffold is refined
 * to a 20 degree minimum angle (the SCAF paper's choices). The public
 * defaults (scaf_options_default in app/param, so atlas_options_default
 * too) and scaffold_default_options take them from here.
 */
#ifndef SCAF_SCAFFOLD_SCAFFOLD_DEFAULTS_H
#define SCAF_SCAFFOLD_SCAFFOLD_DEFAULTS_H

#define SCAFFOLD_DEFAULT_BOX_SCALE 3.0
#define SCAFFOLD_DEFAULT_BOX_POINTS_PER_SIDE 5
#define SCAFFOLD_DEFAULT_MIN_ANGLE_DEG 20.0

#endif /* SCAF_SCAFFOLD_SCAFFOLD_DEFAULTS_H */
