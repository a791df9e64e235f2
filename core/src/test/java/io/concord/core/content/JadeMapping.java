package io.concord.core.content;

import io.concord.core.acl.AID;
import io.concord.core.content.BookShop.Author;
import io.concord.core.content.BookShop.Book;
import io.concord.core.content.BookShop.Owns;
import io.concord.core.content.BookShop.Sell;
import io.concord.core.content.JadeBookShop.JAuthor;
import io.concord.core.content.JadeBookShop.JBook;
import io.concord.core.content.JadeBookShop.JOwns;
import io.concord.core.content.JadeBookShop.JSell;

import java.util.ArrayList;
import java.util.Base64;
import java.util.Date;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Moves the test ontology's objects between Concord's records and JADE's beans, and compares them;
 * turns Concord's abstract content into JADE's.
 */
final class JadeMapping {
    private JadeMapping() {
    }

    static Object toJade(Object o) {
        if (o == null) {
            return null;
        }
        if (o instanceof Action a) {
            return new jade.content.onto.basic.Action((jade.core.AID) toJade(a.actor()), (jade.content.Concept) toJade(a.action()));
        }
        if (o instanceof Done d) {
            return new jade.content.onto.basic.Done((jade.content.onto.basic.Action) toJade(d.action()));
        }
        if (o instanceof Result r) {
            return new jade.content.onto.basic.Result((jade.content.Concept) toJade(r.action()), toJade(r.value()));
        }
        if (o instanceof Equals e) {
            return new jade.content.onto.basic.Equals(toJade(e.left()), toJade(e.right()));
        }
        if (o instanceof TrueProposition) {
            return new jade.content.onto.basic.TrueProposition();
        }
        if (o instanceof FalseProposition) {
            return new jade.content.onto.basic.FalseProposition();
        }
        if (o instanceof AID aid) {
            jade.core.AID j = new jade.core.AID(aid.name(), jade.core.AID.ISGUID);
            aid.addresses().forEach(j::addAddresses);
            return j;
        }
        if (o instanceof Owns w) {
            JOwns j = new JOwns();
            j.setOwner((jade.core.AID) toJade(w.owner()));
            j.setBook((JBook) toJade(w.book()));
            return j;
        }
        if (o instanceof Sell s) {
            JSell j = new JSell();
            j.setBook((JBook) toJade(s.book()));
            j.setMore(s.more() == null ? null : list(s.more()));
            j.setBuyer((jade.core.AID) toJade(s.buyer()));
            j.setRemark(s.remark());
            return j;
        }
        if (o instanceof Book b) {
            JBook j = new JBook();
            j.setTitle(b.title());
            j.setPages(b.pages());
            j.setEdition(b.edition());
            j.setPrice(b.price());
            j.setRating(b.rating());
            j.setUsed(b.used());
            j.setPublished(b.published() == null ? null : Date.from(b.published()));
            j.setCover(b.cover());
            j.setTags(b.tags() == null ? null : new ArrayList<>(b.tags()));
            j.setIsbns(b.isbns() == null ? null : new LinkedHashSet<>(b.isbns()));
            j.setAuthors(b.authors() == null ? null : list(b.authors()));
            return j;
        }
        if (o instanceof Author a) {
            JAuthor j = new JAuthor();
            j.setName(a.name());
            j.setAliases(a.aliases() == null ? null : new ArrayList<>(a.aliases()));
            j.setMentor((JAuthor) toJade(a.mentor()));
            return j;
        }
        throw new IllegalArgumentException("no JADE form for " + o.getClass());
    }

    /**
     * JADE's abstract form of Concord's abstract content, over JADE's ontology: a compound becomes
     * what JADE's schema for its name makes ({@code AbsPredicate}, {@code AbsConcept}, {@code AbsIRE}),
     * a positional argument fills the schema's slot at its position (the order JADE reads and writes
     * them in), and {@code true} or {@code false} where the schema expects a formula becomes JADE's
     * proposition of that name (Concord reads {@code (not true)} with a boolean primitive inside).
     *
     * @param formula whether {@code o} stands where a formula is expected (true for a content element)
     */
    static jade.content.abs.AbsObject toJadeAbs(AbsObject o, jade.content.onto.Ontology ontology, boolean formula)
            throws jade.content.onto.OntologyException {
        if (o instanceof AbsPrimitive p) {
            Object v = p.value();
            if (v instanceof Boolean b && formula) {
                return new jade.content.abs.AbsPredicate(b ? "true" : "false");
            }
            if (v instanceof String s) {
                return jade.content.abs.AbsPrimitive.wrap(s);
            }
            if (v instanceof Boolean b) {
                return jade.content.abs.AbsPrimitive.wrap(b);
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
            if (v instanceof java.time.Instant t) {
                return jade.content.abs.AbsPrimitive.wrap(Date.from(t));
            }
            return jade.content.abs.AbsPrimitive.wrap((byte[]) v);
        }
        if (o instanceof AbsVariable v) {
            return new jade.content.abs.AbsVariable(v.name(), null);
        }
        if (o instanceof AbsAggregate a) {
            jade.content.abs.AbsAggregate j = new jade.content.abs.AbsAggregate(a.type());
            for (AbsObject e : a.elements()) {
                j.add((jade.content.abs.AbsTerm) toJadeAbs(e, ontology, false));
            }
            return j;
        }
        AbsCompound c = (AbsCompound) o;
        jade.content.schema.ObjectSchema schema = ontology.getSchema(c.name());
        if (schema == null) {
            throw new IllegalArgumentException("JADE's ontology has no schema for " + c.name());
        }
        jade.content.abs.AbsObject j = schema.newInstance();
        String[] names = schema.getNames();
        if (c.slots().size() > names.length) {
            throw new IllegalArgumentException(c.name() + " has " + c.slots().size() + " arguments, JADE's schema " + names.length);
        }
        for (int i = 0; i < c.slots().size(); i++) {
            AbsCompound.Slot slot = c.slots().get(i);
            String name = slot.name() != null ? slot.name() : names[i];
            boolean slotIsFormula = schema.getSchema(name) instanceof jade.content.schema.PredicateSchema;
            jade.content.abs.AbsObject value = toJadeAbs(slot.value(), ontology, slotIsFormula);
            if (j instanceof jade.content.abs.AbsIRE ire) {
                if (i == 0) {
                    ire.setVariable((jade.content.abs.AbsVariable) value);
                } else {
                    ire.setProposition((jade.content.abs.AbsPredicate) value);
                }
            } else if (j instanceof jade.content.abs.AbsPredicate p) {
                p.set(name, value);
            } else if (j instanceof jade.content.abs.AbsConcept k) {
                k.set(name, (jade.content.abs.AbsTerm) value);
            } else {
                throw new IllegalArgumentException("no JADE abstract form for " + c.name() + " (" + j.getClass() + ")");
            }
        }
        return j;
    }

    @SuppressWarnings("unchecked")
    private static <T> List<T> list(List<?> l) {
        List<T> out = new ArrayList<>();
        for (Object o : l) {
            out.add((T) toJade(o));
        }
        return out;
    }

    /** A structure with value equality for either side's objects: records, beans, byte arrays, sets. */
    static Object canon(Object o) {
        if (o == null) {
            return null;
        }
        if (o instanceof byte[] b) {
            return "bytes:" + Base64.getEncoder().encodeToString(b);
        }
        if (o instanceof java.util.Collection<?> c && c.isEmpty()) {
            // an empty aggregate is not written (as JADE does), so it reads back as absent
            return null;
        }
        if (o instanceof jade.util.leap.List l && l.isEmpty()) {
            return null;
        }
        if (o instanceof Set<?> s) {
            Set<Object> out = new java.util.HashSet<>();
            s.forEach(e -> out.add(canon(e)));
            return out;
        }
        if (o instanceof jade.util.leap.List l) {
            List<Object> out = new ArrayList<>();
            for (int i = 0; i < l.size(); i++) {
                out.add(canon(l.get(i)));
            }
            return out;
        }
        if (o instanceof List<?> l) {
            List<Object> out = new ArrayList<>();
            l.forEach(e -> out.add(canon(e)));
            return out;
        }
        if (o instanceof Date d) {
            return "date:" + d.getTime();
        }
        if (o instanceof java.time.Instant t) {
            return "date:" + t.toEpochMilli();
        }
        if (o instanceof Integer i) {
            return (long) i;
        }
        if (o instanceof AID a) {
            return List.of("AID", a.name(), a.addresses());
        }
        if (o instanceof jade.core.AID a) {
            return List.of("AID", a.getName(), List.of(a.getAddressesArray()));
        }
        if (o instanceof Action a) {
            return List.of("action", canon(a.actor()), canon(a.action()));
        }
        if (o instanceof jade.content.onto.basic.Action a) {
            return List.of("action", canon(a.getActor()), canon(a.getAction()));
        }
        if (o instanceof Done d) {
            return List.of("done", canon(d.action()));
        }
        if (o instanceof jade.content.onto.basic.Done d) {
            return List.of("done", canon(d.getAction()));
        }
        if (o instanceof Result r) {
            return List.of("result", canon(r.action()), canon(r.value()));
        }
        if (o instanceof jade.content.onto.basic.Result r) {
            return List.of("result", canon(r.getAction()), canon(r.getValue()));
        }
        if (o instanceof Equals e) {
            return List.of("=", canon(e.left()), canon(e.right()));
        }
        if (o instanceof jade.content.onto.basic.Equals e) {
            return List.of("=", canon(e.getLeft()), canon(e.getRight()));
        }
        if (o instanceof TrueProposition || o instanceof jade.content.onto.basic.TrueProposition) {
            return "true";
        }
        if (o instanceof FalseProposition || o instanceof jade.content.onto.basic.FalseProposition) {
            return "false";
        }
        if (o instanceof Owns w) {
            return listOf("Owns", canon(w.owner()), canon(w.book()));
        }
        if (o instanceof JOwns w) {
            return listOf("Owns", canon(w.getOwner()), canon(w.getBook()));
        }
        if (o instanceof Sell s) {
            return listOf("Sell", canon(s.book()), canon(s.more()), canon(s.buyer()), s.remark());
        }
        if (o instanceof JSell s) {
            return listOf("Sell", canon(s.getBook()), canon(s.getMore()), canon(s.getBuyer()), s.getRemark());
        }
        if (o instanceof Book b) {
            return listOf("Book", b.title(), b.pages(), canon(b.edition()), b.price(), b.rating(), b.used(),
                    canon(b.published()), canon(b.cover()), canon(b.tags()), canon(b.isbns()), canon(b.authors()));
        }
        if (o instanceof JBook b) {
            return listOf("Book", b.getTitle(), b.getPages(), canon(b.getEdition()), b.getPrice(), b.getRating(),
                    b.isUsed(), canon(b.getPublished()), canon(b.getCover()), canon(b.getTags()), canon(b.getIsbns()),
                    canon(b.getAuthors()));
        }
        if (o instanceof Author a) {
            return listOf("Author", a.name(), canon(a.aliases()), canon(a.mentor()));
        }
        if (o instanceof JAuthor a) {
            return listOf("Author", a.getName(), canon(a.getAliases()), canon(a.getMentor()));
        }
        return o;
    }

    private static List<Object> listOf(Object... items) {
        return java.util.Arrays.asList(items);
    }
}
