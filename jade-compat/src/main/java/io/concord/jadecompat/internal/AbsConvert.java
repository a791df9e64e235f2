package io.concord.jadecompat.internal;

import io.concord.core.content.AbsAggregate;
import io.concord.core.content.AbsCompound;
import io.concord.core.content.AbsPrimitive;
import io.concord.core.content.AbsVariable;
import jade.content.abs.AbsAgentAction;
import jade.content.abs.AbsConcept;
import jade.content.abs.AbsObject;
import jade.content.abs.AbsObjectImpl;
import jade.content.abs.AbsPredicate;
import jade.content.abs.AbsPrimitiveSlotsHolder;
import jade.content.abs.AbsTerm;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.schema.AgentActionSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PredicateSchema;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Date;
import java.util.List;
import java.util.Map;

/**
 * JADE's abstract descriptors ({@code jade.content.abs}) to core's abstract content and back. The
 * ontology names the slots of elements written by position (predicates, {@code action}, ...); SL's
 * operators are named with JADE's vocabulary ({@code (and left right)}, {@code (not what)}, ...);
 * a referential expression ({@code iota}, {@code any}, {@code all}) is an {@code AbsIRE}.
 */
public final class AbsConvert {
    private static final Map<String, String[]> OPERATORS = Map.ofEntries(
            Map.entry("action", new String[]{"actor", "action"}), Map.entry("done", new String[]{"action", "condition"}),
            Map.entry("result", new String[]{"action", "value"}), Map.entry("=", new String[]{"left", "right"}),
            Map.entry("not", new String[]{"what"}), Map.entry("and", new String[]{"left", "right"}),
            Map.entry("or", new String[]{"left", "right"}), Map.entry("implies", new String[]{"left", "right"}),
            Map.entry("equiv", new String[]{"left", "right"}), Map.entry("forall", new String[]{"what", "condition"}),
            Map.entry("exists", new String[]{"what", "condition"}), Map.entry("B", new String[]{"agent", "condition"}),
            Map.entry("U", new String[]{"agent", "condition"}), Map.entry("PG", new String[]{"agent", "condition"}),
            Map.entry("I", new String[]{"agent", "condition"}), Map.entry("iota", new String[]{"variable", "proposition"}),
            Map.entry("any", new String[]{"variable", "proposition"}), Map.entry("all", new String[]{"variable", "proposition"}));

    private AbsConvert() {
    }

    /** Whether that argument of that operator is a formula, where SL's bare true/false is a proposition. */
    private static boolean formula(String operator, String slot) {
        return switch (operator) {
            case "not", "and", "or", "implies", "equiv" -> true;
            case "forall", "exists", "B", "U", "PG", "I", "done" -> slot.equals("condition");
            case "iota", "any", "all" -> slot.equals("proposition");
            default -> false;
        };
    }

    /** Core's form of a JADE descriptor. */
    public static io.concord.core.content.AbsObject toCore(AbsObject a, Ontology onto) throws OntologyException {
        if (a == null) {
            throw new OntologyException("null has no abstract form");
        }
        if (a instanceof jade.content.abs.AbsPrimitive p) {
            Object v = p.getObject();
            if (v == null) {
                throw new OntologyException("primitive " + p.getTypeName() + " without a value");
            }
            if (v instanceof Date d) {
                v = d.toInstant();
            } else if (v instanceof Short || v instanceof Byte) {
                v = ((Number) v).longValue();
            }
            return new AbsPrimitive(v);
        }
        if (a instanceof jade.content.abs.AbsVariable v) {
            return new AbsVariable(v.getName());
        }
        if (a instanceof jade.content.abs.AbsAggregate g) {
            List<io.concord.core.content.AbsObject> out = new ArrayList<>();
            for (int i = 0; i < g.size(); i++) {
                out.add(toCore(g.get(i), onto));
            }
            return new AbsAggregate(AbsAggregate.SET.equals(g.getTypeName()) ? AbsAggregate.SET : AbsAggregate.SEQUENCE, out);
        }
        if (!(a instanceof AbsObjectImpl)) {
            throw new OntologyException("cannot write a " + a.getClass().getSimpleName() + " here");
        }
        String name = a.getTypeName();
        if ((name.equals("true") || name.equals("false")) && a.getCount() == 0) {
            return new AbsPrimitive(name.equals("true"));
        }
        ObjectSchema schema = onto == null ? null : onto.getSchema(name);
        boolean positional = schema != null
                ? schema instanceof PredicateSchema || schema.getEncodingByOrder()
                : OPERATORS.containsKey(name) || a instanceof AbsPredicate;
        List<String> order = new ArrayList<>();
        String[] known = schema != null ? schema.getNames() : OPERATORS.get(name);
        if (known != null) {
            for (String n : known) {
                if (a.getAbsObject(n) != null) {
                    order.add(n);
                }
            }
        }
        for (String n : a.getNames()) {
            if (!order.contains(n)) {
                order.add(n);
            }
        }
        List<AbsCompound.Slot> slots = new ArrayList<>();
        for (String n : order) {
            slots.add(new AbsCompound.Slot(positional ? null : n, toCore(a.getAbsObject(n), onto)));
        }
        return new AbsCompound(name, slots);
    }

    /** JADE's descriptor of core's form; at the top of a content, SL's bare {@code true}/{@code false} is a predicate. */
    public static AbsObject fromCore(io.concord.core.content.AbsObject a, Ontology onto, boolean top) throws OntologyException {
        if (a instanceof AbsPrimitive p) {
            Object v = p.value();
            if (v instanceof Boolean b) {
                return top ? new AbsPredicate(b ? "true" : "false") : jade.content.abs.AbsPrimitive.wrap(b);
            }
            if (v instanceof String s) {
                return jade.content.abs.AbsPrimitive.wrap(s);
            }
            if (v instanceof Long l) {
                return jade.content.abs.AbsPrimitive.wrap(l.longValue());
            }
            if (v instanceof Integer i) {
                return jade.content.abs.AbsPrimitive.wrap(i.intValue());
            }
            if (v instanceof Double d) {
                return jade.content.abs.AbsPrimitive.wrap(d.doubleValue());
            }
            if (v instanceof Float f) {
                return jade.content.abs.AbsPrimitive.wrap(f.floatValue());
            }
            if (v instanceof Instant t) {
                return jade.content.abs.AbsPrimitive.wrap(Date.from(t));
            }
            return jade.content.abs.AbsPrimitive.wrap((byte[]) v);
        }
        if (a instanceof AbsVariable v) {
            return new jade.content.abs.AbsVariable(v.name(), null);
        }
        if (a instanceof AbsAggregate g) {
            jade.content.abs.AbsAggregate out = new jade.content.abs.AbsAggregate(g.type());
            for (io.concord.core.content.AbsObject e : g.elements()) {
                AbsObject x = fromCore(e, onto, false);
                if (!(x instanceof AbsTerm t)) {
                    throw new OntologyException("a " + g.type() + " holds terms, not " + x.getTypeName());
                }
                out.add(t);
            }
            return out;
        }
        AbsCompound c = (AbsCompound) a;
        String name = c.name();
        if ((name.equals("iota") || name.equals("any") || name.equals("all")) && !c.isNamed() && c.slots().size() == 2) {
            jade.content.abs.AbsIRE ire = new jade.content.abs.AbsIRE(name);
            AbsObject term = fromCore(c.slots().get(0).value(), onto, false);
            AbsObject proposition = fromCore(c.slots().get(1).value(), onto, true);
            if (!(term instanceof AbsTerm t) || !(proposition instanceof AbsPredicate p)) {
                throw new OntologyException(name + " takes a term and a proposition");
            }
            ire.setTerm(t);
            ire.setProposition(p);
            return ire;
        }
        ObjectSchema schema = onto == null ? null : onto.getSchema(name);
        AbsPrimitiveSlotsHolder out;
        if (schema instanceof AgentActionSchema) {
            out = new AbsAgentAction(name);
        } else if (schema instanceof ConceptSchema) {
            out = new AbsConcept(name);
        } else if (schema instanceof PredicateSchema || OPERATORS.containsKey(name) || !c.isNamed()) {
            out = new AbsPredicate(name);
        } else {
            out = new AbsConcept(name);
        }
        String[] names = schema != null ? schema.getNames() : OPERATORS.get(name);
        for (int i = 0; i < c.slots().size(); i++) {
            AbsCompound.Slot s = c.slots().get(i);
            String slot = s.name() != null ? s.name() : names != null && i < names.length ? names[i] : Integer.toString(i);
            out.set(slot, fromCore(s.value(), onto, formula(name, slot)));
        }
        return out;
    }
}
