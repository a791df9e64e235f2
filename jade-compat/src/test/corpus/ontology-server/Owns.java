import jade.content.Predicate;

/** A predicate the shop serves when asked with QUERY_IF (serveOwnsQueryIf), not when told with INFORM. */
public class Owns implements Predicate {
    private String item;

    public String getItem() {
        return item;
    }

    public void setItem(String item) {
        this.item = item;
    }
}
