# Two lots in local metres: a 10 x 6 rectangle 5 high and a 4 x 4 square 2 high.
cat > lots.geojson <<'G'
{"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
 "features": [
  {"type": "Feature", "id": "a", "properties": {"height": 5}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]]}},
  {"type": "Feature", "id": "b", "properties": {"height": 2}, "geometry": {"type": "Polygon", "coordinates": [[[20, 0], [24, 0], [24, 4], [20, 4], [20, 0]]]}}]}
G
