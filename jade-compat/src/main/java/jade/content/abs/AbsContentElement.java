package jade.content.abs;

import jade.content.ContentElement;

/** An abstract content element: a predicate, an agent action, or a list of them. */
public interface AbsContentElement extends AbsObject, ContentElement {
    /** Whether it is a whole content rather than a part of one. */
    boolean isAContentExpression();

    /** Marks it a whole content or not. */
    void setIsAContentExpression(boolean flag);
}
