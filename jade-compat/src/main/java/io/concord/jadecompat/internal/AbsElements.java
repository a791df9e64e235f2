package io.concord.jadecompat.internal;

import jade.content.abs.AbsContentElement;
import jade.content.abs.AbsContentElementList;
import jade.content.abs.AbsObject;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;

import java.util.ArrayList;
import java.util.List;

/** A content's elements: JADE's one descriptor (or list of them) to core's list, and back. */
public final class AbsElements {
    private AbsElements() {
    }

    /** Core's elements of a JADE content element (each element of a list). */
    public static List<io.concord.core.content.AbsObject> toCore(Ontology onto, AbsContentElement content) throws OntologyException {
        if (content == null) {
            throw new OntologyException("null content");
        }
        List<io.concord.core.content.AbsObject> out = new ArrayList<>();
        if (content instanceof AbsContentElementList l) {
            for (int i = 0; i < l.size(); i++) {
                out.add(AbsConvert.toCore(l.get(i), onto));
            }
        } else {
            out.add(AbsConvert.toCore(content, onto));
        }
        return out;
    }

    /** JADE's content element of core's elements: the element, or a list of several. */
    public static AbsContentElement fromCore(Ontology onto, List<io.concord.core.content.AbsObject> elements) throws OntologyException {
        if (elements.isEmpty()) {
            throw new OntologyException("the content has no element");
        }
        List<AbsContentElement> out = new ArrayList<>();
        for (io.concord.core.content.AbsObject e : elements) {
            AbsObject a = AbsConvert.fromCore(e, onto, true);
            if (!(a instanceof AbsContentElement ce)) {
                throw new OntologyException("content element " + a.getTypeName() + " is neither a predicate nor an agent action");
            }
            ce.setIsAContentExpression(true);
            out.add(ce);
        }
        if (out.size() == 1) {
            return out.get(0);
        }
        AbsContentElementList l = new AbsContentElementList();
        for (AbsContentElement ce : out) {
            l.add(ce);
        }
        l.setIsAContentExpression(true);
        return l;
    }
}
