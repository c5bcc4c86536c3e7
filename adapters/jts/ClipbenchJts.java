import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.locationtech.jts.JTSVersion;
import org.locationtech.jts.algorithm.InteriorPointArea;
import org.locationtech.jts.algorithm.Orientation;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.LinearRing;
import org.locationtech.jts.geom.Point;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.operation.overlayng.OverlayNG;
import org.locationtech.jts.operation.overlayng.OverlayNGRobust;
import org.locationtech.jts.operation.polygonize.Polygonizer;

/**
 * JTS's OverlayNG behind clipbench's external clipper protocol, version 1 (docs/PROTOCOL.md).
 *
 * <p>{@code java ClipbenchJts ng} runs {@code OverlayNG.overlay} in floating precision, as is;
 * {@code java ClipbenchJts ng-robust} runs {@code OverlayNGRobust.overlay}, which retries a failed
 * overlay with snapping and then snap rounding. JTS takes valid polygons only, so each operand's
 * region under the requested fill rule is built first, as the shapely adapter does: the rings'
 * lines are noded together (OverlayNGRobust's unary union), polygonized into faces, and a face is
 * kept when the fill rule accepts the input rings' winding number around a point inside it; the
 * kept faces, unioned, are a valid polygon. {@code time_ns} covers the overlay call only.
 */
public final class ClipbenchJts {
  private static final GeometryFactory FACTORY = new GeometryFactory();
  private static final String[] OPS = {"intersection", "union", "difference", "xor"};
  private static final String[] FILLS = {"even-odd", "non-zero", "positive", "negative"};

  private ClipbenchJts() {}

  public static void main(String[] args) throws Exception {
    if (args.length != 1 || !(args[0].equals("ng") || args[0].equals("ng-robust"))) {
      System.err.println("usage: java ClipbenchJts ng|ng-robust");
      System.exit(2);
    }
    boolean robust = args[0].equals("ng-robust");
    BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
    BufferedWriter out = new BufferedWriter(new OutputStreamWriter(System.out, StandardCharsets.UTF_8));
    String name = "JTS " + JTSVersion.CURRENT_VERSION + (robust ? " OverlayNGRobust" : " OverlayNG (floating)")
        + " (operands as valid polygons built by JTS)";
    out.write("{\"protocol\":1,\"name\":" + Json.quote(name) + ",\"polygon\":{\"ops\":" + Json.strings(OPS)
        + ",\"fill_rules\":" + Json.strings(FILLS) + ",\"window\":\"any\",\"output\":\"conventional\"}}\n");
    out.flush();
    String line;
    while ((line = in.readLine()) != null) {
      if (line.isBlank()) {
        continue;
      }
      Map<String, Object> request = Json.object(line);
      long id = ((Double) request.get("id")).longValue();
      String reply;
      try {
        reply = answer(id, request, robust);
      } catch (Exception | StackOverflowError e) {
        // A JTS exception (TopologyException, ...) becomes an error reply: the case fails, the process goes on.
        String what = e.getClass().getSimpleName() + ": " + e.getMessage();
        reply = "{\"id\":" + id + ",\"error\":" + Json.quote(what) + "}";
      }
      out.write(reply);
      out.write('\n');
      out.flush();
    }
  }

  private static String answer(long id, Map<String, Object> request, boolean robust) {
    String op = (String) request.get("op");
    String fill = (String) request.get("fill");
    int code = switch (op) {
      case "intersection" -> OverlayNG.INTERSECTION;
      case "union" -> OverlayNG.UNION;
      case "difference" -> OverlayNG.DIFFERENCE;
      case "xor" -> OverlayNG.SYMDIFFERENCE;
      default -> throw new IllegalArgumentException("unknown operation '" + op + "'");
    };
    Geometry a;
    Geometry b;
    try {
      a = region(rings(request.get("subject")), fill);
      b = region(rings(request.get("clip")), fill);
    } catch (RuntimeException e) {
      // The reader's failure (JTS building a region from crossing rings), not the overlay's: say so.
      throw new IllegalStateException("reading the operands failed, before the overlay ran: "
          + e.getClass().getSimpleName() + ": " + e.getMessage(), e);
    }
    long start = System.nanoTime();
    Geometry result = robust ? OverlayNGRobust.overlay(a, b, code) : OverlayNG.overlay(a, b, code);
    long time = System.nanoTime() - start;
    StringBuilder s = new StringBuilder("{\"id\":").append(id).append(",\"rings\":[");
    boolean[] first = {true};
    writeRings(result, s, first);
    return s.append("],\"time_ns\":").append(time).append('}').toString();
  }

  /** The request's rings as coordinate lists, the closing point not repeated. */
  @SuppressWarnings("unchecked")
  private static List<double[][]> rings(Object value) {
    List<double[][]> rings = new ArrayList<>();
    for (Object ring : (List<Object>) value) {
      List<Object> points = (List<Object>) ring;
      double[][] r = new double[points.size()][];
      for (int i = 0; i < r.length; i++) {
        List<Object> p = (List<Object>) points.get(i);
        r[i] = new double[] {(Double) p.get(0), (Double) p.get(1)};
      }
      rings.add(r);
    }
    return rings;
  }

  /** Winding number of the rings around (px, py): the crossing rule, counter-clockwise loops +1. */
  static int windingNumber(List<double[][]> rings, double px, double py) {
    int w = 0;
    for (double[][] ring : rings) {
      for (int i = 0, j = ring.length - 1; i < ring.length; j = i++) {
        double ax = ring[j][0], ay = ring[j][1], bx = ring[i][0], by = ring[i][1];
        double cross = (bx - ax) * (py - ay) - (px - ax) * (by - ay);
        if (ay <= py && by > py && cross > 0) {
          w++;
        } else if (ay > py && by <= py && cross < 0) {
          w--;
        }
      }
    }
    return w;
  }

  static boolean inside(int w, String fill) {
    return switch (fill) {
      case "even-odd" -> w % 2 != 0;
      case "non-zero" -> w != 0;
      case "positive" -> w > 0;
      case "negative" -> w < 0;
      default -> throw new IllegalArgumentException("unknown fill rule '" + fill + "'");
    };
  }

  /** The region the rings cover under the fill rule, as a valid polygonal geometry. */
  static Geometry region(List<double[][]> rings, String fill) {
    inside(0, fill);
    if (rings.isEmpty()) {
      return FACTORY.createPolygon();
    }
    LineString[] lines = new LineString[rings.size()];
    for (int k = 0; k < lines.length; k++) {
      double[][] r = rings.get(k);
      Coordinate[] c = new Coordinate[r.length + 1];
      for (int i = 0; i < r.length; i++) {
        c[i] = new Coordinate(r[i][0], r[i][1]);
      }
      c[r.length] = c[0].copy();
      lines[k] = FACTORY.createLineString(c);
    }
    Geometry noded = OverlayNGRobust.union(FACTORY.createMultiLineString(lines));
    Polygonizer polygonizer = new Polygonizer();
    polygonizer.add(noded);
    List<Polygon> kept = new ArrayList<>();
    for (Object face : polygonizer.getPolygons()) {
      Polygon p = (Polygon) face;
      Coordinate q = InteriorPointArea.getInteriorPoint(p);
      if (q != null && inside(windingNumber(rings, q.x, q.y), fill)) {
        kept.add(p);
      }
    }
    if (kept.isEmpty()) {
      return FACTORY.createPolygon();
    }
    return OverlayNGRobust.union(FACTORY.createMultiPolygon(kept.toArray(new Polygon[0])));
  }

  /** Every polygon ring of a result, outers counter-clockwise and holes clockwise; points and lines dropped. */
  private static void writeRings(Geometry g, StringBuilder s, boolean[] first) {
    if (g.isEmpty()) {
      return;
    }
    if (g instanceof Polygon p) {
      writeRing(p.getExteriorRing(), true, s, first);
      for (int i = 0; i < p.getNumInteriorRing(); i++) {
        writeRing(p.getInteriorRingN(i), false, s, first);
      }
    } else if (!(g instanceof Point) && !(g instanceof LineString)) {
      for (int i = 0; i < g.getNumGeometries(); i++) {
        Geometry part = g.getGeometryN(i);
        if (part != g) {
          writeRings(part, s, first);
        }
      }
    }
  }

  private static void writeRing(LinearRing ring, boolean outer, StringBuilder s, boolean[] first) {
    Coordinate[] c = ring.getCoordinates();
    int n = c.length - 1;
    if (n < 3) {
      return;
    }
    boolean reverse = Orientation.isCCW(c) != outer;
    s.append(first[0] ? "[" : ",[");
    first[0] = false;
    for (int i = 0; i < n; i++) {
      Coordinate q = c[reverse ? n - 1 - i : i];
      s.append(i == 0 ? "[" : ",[").append(Json.number(q.x)).append(',').append(Json.number(q.y)).append(']');
    }
    s.append(']');
  }

  /** Just enough JSON for the protocol's requests: objects, arrays, numbers, strings, true/false/null. */
  static final class Json {
    private final String text;
    private int at;

    private Json(String text) {
      this.text = text;
    }

    @SuppressWarnings("unchecked")
    static Map<String, Object> object(String text) {
      Json j = new Json(text);
      Object v = j.value();
      j.space();
      if (!(v instanceof Map) || j.at != text.length()) {
        throw new IllegalArgumentException("a request must be one JSON object on one line");
      }
      return (Map<String, Object>) v;
    }

    static String number(double x) {
      // Java's Double.toString round-trips exactly; JSON takes its exponent form ("1.0E10").
      return Double.toString(x);
    }

    static String quote(String s) {
      StringBuilder b = new StringBuilder("\"");
      for (char c : s.toCharArray()) {
        if (c == '"' || c == '\\') {
          b.append('\\').append(c);
        } else if (c < 0x20) {
          b.append(String.format("\\u%04x", (int) c));
        } else {
          b.append(c);
        }
      }
      return b.append('"').toString();
    }

    static String strings(String[] values) {
      StringBuilder b = new StringBuilder("[");
      for (int i = 0; i < values.length; i++) {
        b.append(i == 0 ? "" : ",").append(quote(values[i]));
      }
      return b.append(']').toString();
    }

    private void space() {
      while (at < text.length() && Character.isWhitespace(text.charAt(at))) {
        at++;
      }
    }

    private Object value() {
      space();
      if (at >= text.length()) {
        throw new IllegalArgumentException("unexpected end of the line");
      }
      char c = text.charAt(at);
      if (c == '{') {
        Map<String, Object> m = new LinkedHashMap<>();
        at++;
        space();
        if (text.charAt(at) == '}') {
          at++;
          return m;
        }
        while (true) {
          space();
          String key = string();
          space();
          expect(':');
          m.put(key, value());
          space();
          if (text.charAt(at) == ',') {
            at++;
          } else {
            expect('}');
            return m;
          }
        }
      }
      if (c == '[') {
        List<Object> list = new ArrayList<>();
        at++;
        space();
        if (text.charAt(at) == ']') {
          at++;
          return list;
        }
        while (true) {
          list.add(value());
          space();
          if (text.charAt(at) == ',') {
            at++;
          } else {
            expect(']');
            return list;
          }
        }
      }
      if (c == '"') {
        return string();
      }
      for (String word : new String[] {"true", "false", "null"}) {
        if (text.startsWith(word, at)) {
          at += word.length();
          return word.equals("null") ? null : Boolean.valueOf(word);
        }
      }
      int start = at;
      while (at < text.length() && "+-0123456789.eE".indexOf(text.charAt(at)) >= 0) {
        at++;
      }
      if (start == at) {
        throw new IllegalArgumentException("unexpected '" + c + "' at column " + (at + 1));
      }
      return Double.parseDouble(text.substring(start, at));
    }

    private String string() {
      expect('"');
      StringBuilder b = new StringBuilder();
      while (text.charAt(at) != '"') {
        char c = text.charAt(at++);
        if (c == '\\') {
          char e = text.charAt(at++);
          switch (e) {
            case 'n' -> b.append('\n');
            case 't' -> b.append('\t');
            case 'r' -> b.append('\r');
            case 'b' -> b.append('\b');
            case 'f' -> b.append('\f');
            case 'u' -> {
              b.append((char) Integer.parseInt(text.substring(at, at + 4), 16));
              at += 4;
            }
            default -> b.append(e);
          }
        } else {
          b.append(c);
        }
      }
      at++;
      return b.toString();
    }

    private void expect(char c) {
      if (at >= text.length() || text.charAt(at) != c) {
        throw new IllegalArgumentException("expected '" + c + "' at column " + (at + 1));
      }
      at++;
    }
  }
}
