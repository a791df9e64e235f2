package jade.content.abs;

import jade.util.leap.ArrayList;
import jade.util.leap.Iterator;
import jade.util.leap.List;

/** Several abstract content elements sent as one content. */
public class AbsContentElementList implements AbsContentElement {
    private static final long serialVersionUID = 1L;
    private final List elements = new ArrayList();
    private boolean contentExpression;

    /** An empty list. */
    public AbsContentElementList() {
    }

    /** Appends an element. */
    public void add(AbsContentElement element) {
        elements.add(element);
    }

    /** How many elements it has. */
    public int size() {
        return elements.size();
    }

    /** The element at that index. */
    public AbsContentElement get(int i) {
        return (AbsContentElement) elements.get(i);
    }

    /** Its elements in order. */
    public Iterator iterator() {
        return elements.iterator();
    }

    /** Removes every element. */
    public void clear() {
        elements.clear();
    }

    /** Whether it holds that element. */
    public boolean contains(AbsContentElement element) {
        return elements.contains(element);
    }

    /** The element's index, or -1. */
    public int indexOf(AbsContentElement element) {
        return elements.indexOf(element);
    }

    /** Removes and returns the element at that index. */
    public AbsContentElement remove(int i) {
        return (AbsContentElement) elements.remove(i);
    }

    /** Whether it has no element. */
    public boolean isEmpty() {
        return elements.isEmpty();
    }

    /** Its elements as an array. */
    public AbsContentElement[] toArray() {
        AbsContentElement[] out = new AbsContentElement[elements.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = get(i);
        }
        return out;
    }

    /** Its type name, JADE's {@code BasicOntology.CONTENT_ELEMENT_LIST}. */
    @Override
    public String getTypeName() {
        return jade.content.onto.BasicOntology.CONTENT_ELEMENT_LIST;
    }

    /** The element at the index the name gives, or null. */
    @Override
    public AbsObject getAbsObject(String name) {
        try {
            int i = Integer.parseInt(name);
            return i >= 0 && i < elements.size() ? get(i) : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** The element indexes as names. */
    @Override
    public String[] getNames() {
        String[] out = new String[elements.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = Integer.toString(i);
        }
        return out;
    }

    @Override
    public boolean isGrounded() {
        for (int i = 0; i < elements.size(); i++) {
            if (!get(i).isGrounded()) {
                return false;
            }
        }
        return true;
    }

    @Override
    public int getCount() {
        return elements.size();
    }

    @Override
    public String toString() {
        return elements.toString();
    }

    @Override
    public int hashCode() {
        return elements.hashCode();
    }

    @Override
    public boolean isAContentExpression() {
        return contentExpression;
    }

    @Override
    public void setIsAContentExpression(boolean flag) {
        this.contentExpression = flag;
    }

    @Override
    public int getAbsType() {
        return ABS_CONTENT_ELEMENT_LIST;
    }
}
