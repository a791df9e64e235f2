import jade.content.Predicate;
import jade.core.AID;

/** The proposition that an agent owns a book. */
public class Owns implements Predicate {
    private AID owner;
    private Book book;

    public AID getOwner() {
        return owner;
    }

    public void setOwner(AID owner) {
        this.owner = owner;
    }

    public Book getBook() {
        return book;
    }

    public void setBook(Book book) {
        this.book = book;
    }
}
