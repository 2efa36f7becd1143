# Sourced by the bench scripts: one long query per shared polygon world, "world start goal",
# through free space (points found by a scan for clearance >= 0.8).
POLYGON_QUERIES=(
  "parking1 1.0,7.2 17.6,7.2"
  "parking3 1.0,12.35 35.7,16.35"
  "warehouse 4.93,9.46 80.84,75.84"
  "warehouse2 5.29,5.89 119.19,76.02"
)
