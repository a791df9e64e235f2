package io.concord.core.content;

import io.concord.core.acl.AID;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Date;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The basic ontology every other extends, as JADE's {@code BasicOntology}: primitives, aggregates,
 * {@code agent-identifier} ({@link AID}), {@code action} ({@link Action}), {@code done}
 * ({@link Done}), {@code result} ({@link Result}), {@code =} ({@link Equals}), {@code true}
 * ({@link TrueProposition}) and {@code false} ({@link FalseProposition}). The last two are written
 * as SL's bare {@code true} and {@code false} (a boolean where a formula belongs); {@code (true)}
 * is read as well.
 */
public final class BasicOntology implements Ontology {

    /** Its name. */
    public static final String NAME = "basic-ontology";
    /** The one instance. */
    public static final BasicOntology INSTANCE = new BasicOntology();

    private static final Map<String, Schema> SCHEMAS = Map.ofEntries(
            primitive("string", String.class), primitive("integer", Long.class), primitive("float", Double.class),
            primitive("boolean", Boolean.class), primitive("date", Instant.class), primitive("byte-sequence", byte[].class),
            Map.entry(AbsAggregate.SEQUENCE, new Schema(AbsAggregate.SEQUENCE, Schema.Kind.AGGREGATE, List.class, List.of())),
            Map.entry(AbsAggregate.SET, new Schema(AbsAggregate.SET, Schema.Kind.AGGREGATE, Set.class, List.of())),
            Map.entry("agent-identifier", new Schema("agent-identifier", Schema.Kind.CONCEPT, AID.class, List.of(
                    new Schema.SlotSchema("name", String.class, null, true, 0, -1),
                    new Schema.SlotSchema("addresses", String.class, AbsAggregate.SEQUENCE, false, 0, -1),
                    new Schema.SlotSchema("resolvers", AID.class, AbsAggregate.SEQUENCE, false, 0, -1)))),
            Map.entry("action", new Schema("action", Schema.Kind.AGENT_ACTION, Action.class, List.of(
                    new Schema.SlotSchema("actor", AID.class, null, true, 0, -1),
                    new Schema.SlotSchema("action", Object.class, null, true, 0, -1)))),
            Map.entry("done", new Schema("done", Schema.Kind.PREDICATE, Done.class, List.of(
                    new Schema.SlotSchema("action", Action.class, null, true, 0, -1)))),
            Map.entry("result", new Schema("result", Schema.Kind.PREDICATE, Result.class, List.of(
                    new Schema.SlotSchema("action", Action.class, null, true, 0, -1),
                    new Schema.SlotSchema("value", Object.class, null, true, 0, -1)))),
            Map.entry("=", new Schema("=", Schema.Kind.PREDICATE, Equals.class, List.of(
                    new Schema.SlotSchema("left", Object.class, null, true, 0, -1),
                    new Schema.SlotSchema("right", Object.class, null, true, 0, -1)))),
            Map.entry("true", new Schema("true", Schema.Kind.PREDICATE, TrueProposition.class, List.of())),
            Map.entry("false", new Schema("false", Schema.Kind.PREDICATE, FalseProposition.class, List.of())));

    private BasicOntology() {
    }

    private static Map.Entry<String, Schema> primitive(String name, Class<?> type) {
        return Map.entry(name, new Schema(name, Schema.Kind.PRIMITIVE, type, List.of()));
    }

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public Schema schema(String symbol) {
        return SCHEMAS.get(symbol);
    }

    @Override
    public Collection<Schema> schemas() {
        return SCHEMAS.values();
    }

    @Override
    public AbsObject toAbs(Object value) throws ContentException {
        return new Mapper(this, Map.of()).toAbs(value);
    }

    @Override
    public Object fromAbs(AbsObject abs) throws ContentException {
        return new Mapper(this, Map.of()).fromAbs(abs, Object.class, "content");
    }

    /** The abstract form of a basic value, or null when it is not one. */
    static AbsObject basicToAbs(Object v, Mapper m) throws ContentException {
        if (v instanceof String || v instanceof Boolean || v instanceof Long || v instanceof Integer
                || v instanceof Double || v instanceof Float || v instanceof Instant || v instanceof byte[]) {
            return new AbsPrimitive(v);
        }
        if (v instanceof Date d) {
            return new AbsPrimitive(d.toInstant());
        }
        if (v instanceof AID aid) {
            List<AbsCompound.Slot> slots = new ArrayList<>();
            slots.add(new AbsCompound.Slot("name", new AbsPrimitive(aid.name())));
            if (!aid.addresses().isEmpty()) {
                slots.add(new AbsCompound.Slot("addresses", new AbsAggregate(AbsAggregate.SEQUENCE,
                        aid.addresses().stream().<AbsObject>map(AbsPrimitive::new).toList())));
            }
            if (!aid.resolvers().isEmpty()) {
                List<AbsObject> rs = new ArrayList<>();
                for (AID r : aid.resolvers()) {
                    rs.add(basicToAbs(r, m));
                }
                slots.add(new AbsCompound.Slot("resolvers", new AbsAggregate(AbsAggregate.SEQUENCE, rs)));
            }
            return new AbsCompound("agent-identifier", slots);
        }
        if (v instanceof Action a) {
            return AbsCompound.positional("action", basicToAbs(a.actor(), m), m.toAbs(a.action()));
        }
        if (v instanceof Done d) {
            return AbsCompound.positional("done", m.toAbs(required(d.action(), "done", "action")));
        }
        if (v instanceof Result r) {
            return AbsCompound.positional("result", m.toAbs(required(r.action(), "result", "action")),
                    m.toAbs(required(r.value(), "result", "value")));
        }
        if (v instanceof Equals e) {
            return AbsCompound.positional("=", m.toAbs(required(e.left(), "=", "left")),
                    m.toAbs(required(e.right(), "=", "right")));
        }
        // SL's true and false are bare atomic formulas, as JADE writes them: (and true (not false))
        if (v instanceof TrueProposition) {
            return new AbsPrimitive(Boolean.TRUE);
        }
        if (v instanceof FalseProposition) {
            return new AbsPrimitive(Boolean.FALSE);
        }
        if (v instanceof Set<?> s) {
            return new AbsAggregate(AbsAggregate.SET, m.toAbsAll(s));
        }
        if (v instanceof Collection<?> c) {
            return new AbsAggregate(AbsAggregate.SEQUENCE, m.toAbsAll(c));
        }
        return null;
    }

    private static Object required(Object v, String symbol, String slot) throws ContentException {
        if (v == null) {
            throw new ContentException("missing mandatory slot :" + slot + " of " + symbol);
        }
        return v;
    }

    /** The Java value of a basic compound, or null when the symbol is not a basic one. */
    static Object basicFromAbs(AbsCompound c, Mapper m) throws ContentException {
        switch (c.name()) {
            case "agent-identifier": {
                Object name = m.slot(c, 0, "name", String.class, null);
                if (name == null) {
                    throw new ContentException("missing mandatory slot :name of agent-identifier");
                }
                List<?> addresses = (List<?>) m.slot(c, 1, "addresses", String.class, AbsAggregate.SEQUENCE);
                List<?> resolvers = (List<?>) m.slot(c, 2, "resolvers", AID.class, AbsAggregate.SEQUENCE);
                m.noOtherSlots(c, Set.of("name", "addresses", "resolvers"));
                return new AID((String) name, addresses == null ? List.of() : strings(addresses),
                        resolvers == null ? List.of() : aids(resolvers), Map.of());
            }
            case "action":
                return new Action((AID) m.positional(c, 0, AID.class), m.positional(c, 1, Object.class));
            case "done":
                return new Done((Action) m.positional(c, 0, Action.class));
            case "result":
                return new Result((Action) m.positional(c, 0, Action.class), m.positional(c, 1, Object.class));
            case "=":
                return new Equals(m.positional(c, 0, Object.class), m.positional(c, 1, Object.class));
            case "true":
                m.arity(c, 0);
                return new TrueProposition();
            case "false":
                m.arity(c, 0);
                return new FalseProposition();
            default:
                return null;
        }
    }

    private static List<String> strings(List<?> l) {
        List<String> r = new ArrayList<>();
        for (Object o : l) {
            r.add((String) o);
        }
        return r;
    }

    private static List<AID> aids(List<?> l) {
        List<AID> r = new ArrayList<>();
        for (Object o : l) {
            r.add((AID) o);
        }
        return r;
    }

    /** A set for a decoded {@code set}, keeping the written order. */
    static Set<Object> newSet(List<Object> elements) {
        return new LinkedHashSet<>(elements);
    }
}
